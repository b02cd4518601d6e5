#include "contactbench/app/load_fields.hpp"

#include "contactbench/app/field_picture.hpp"
#include "contactbench/app/stages.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

std::vector<const char*> field_quantities(bool adhesive) {
  if (adhesive) return {"pressure", "gap", "contact", "attraction"};
  return {"pressure", "gap", "contact"};
}

std::vector<std::string> write_load_fields(const std::string& prefix, std::size_t k, const Grid& grid,
                                           const LoadFields& fields,
                                           const std::function<void(const std::string&)>& warning) {
  // The contact set as classes: the solver's contact is where the repulsive pressure is > 0 (its own
  // definition, ContactSolution); the attractive zone is pulled (a > 0) without touching.
  HeightMap contact = (*fields.pressure > 0).cast<Real>();
  if (fields.attraction != nullptr)
    contact = (*fields.pressure <= 0 && *fields.attraction > 0).select(Real(2), contact);
  std::vector<std::string> written;
  const auto write = [&](const char* quantity, const HeightMap& values, const char* unit) {
    const std::string path = field_path(prefix, k, quantity);
    write_field(path, Field{Surface(grid, values), quantity, unit});
    written.push_back(path);
  };
  write("pressure", *fields.pressure, "Pa");
  write("gap", *fields.gap, "m");
  write("contact", contact, "1");
  if (fields.attraction != nullptr) write("attraction", *fields.attraction, "Pa");
  if (grid.points() > kMostPicturePoints) {
    if (k == 1 && warning)
      warning("fields of " + std::to_string(grid.nx) + " x " + std::to_string(grid.ny) +
              " points are written as text only (maps up to " + std::to_string(kMostPicturePoints) +
              " points); draw one with `contactbench plot " + written.front() + "`");
    return written;
  }
  const std::size_t texts = written.size();
  try {
    for (std::size_t f = 0; f < texts; ++f) {
      const std::string stem = written[f].substr(0, written[f].size() - 4);  // less ".txt"
      draw_field_picture(written[f], stem + ".png", stem + ".svg");
      written.push_back(stem + ".png");
      written.push_back(stem + ".svg");
    }
  } catch (const Error& e) {
    if (warning) warning(std::string("no maps of the fields: ") + e.what());
  }
  return written;
}

}  // namespace contactbench
