#include "contactbench/app/scene_grid_override.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "contactbench/app/problems.hpp"
#include "contactbench/app/scene_text.hpp"
#include "contactbench/app/scene_toml.hpp"
#include "contactbench/app/section.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/grid.hpp"

namespace contactbench {

namespace {

std::optional<std::string> generator_refusal(const SelfAffinePsd& psd, Real size, Index points) {
  try {
    validate(psd, Grid{.nx = points, .ny = points, .lx = size, .ly = size, .periodic = true});
    return std::nullopt;
  } catch (const Error& error) {
    return std::string(error.what());
  }
}

// The least points a side on which the generator takes the spectrum. Each condition validate() checks (qs
// at most Nyquist, qr below qs, qs above the lattice's lowest wavevector 2 pi/L) holds on every grid finer
// than the least one that meets it (Nyquist grows with the points, 2 pi/L does not change), so a bisection
// finds it; `valid` is a grid known to be valid (the scene's own).
Index least_valid_points(const SelfAffinePsd& psd, Real size, Index valid) {
  Index invalid = 1;  // a grid of 1 point has no Nyquist mode: treated as invalid, grids start at 2
  while (valid - invalid > 1) {
    const Index middle = invalid + (valid - invalid) / 2;
    (generator_refusal(psd, size, middle) ? invalid : valid) = middle;
  }
  return valid;
}

// A refine key (points a side) scaled with the grid: the nearest integer, never below the new grid.
Index scaled_points(Index refine, Index from, Index to) {
  const auto scaled = static_cast<Index>(
      std::llround(static_cast<double>(refine) * static_cast<double>(to) / static_cast<double>(from)));
  return std::max(scaled, to);
}

}  // namespace

toml::table with_grid_override(const toml::table& document, const Scene& as_written, Index points,
                               const std::filesystem::path& origin) {
  Problems problems(origin.empty() ? "<scene>" : origin.string());
  const toml::table& surface_table = *document["surface"].as_table();  // present: as_written was parsed
  const std::string flag = "--grid " + std::to_string(points);
  if (const auto* file = std::get_if<FileSurfaceSpec>(&as_written.surface.source)) {
    problems.add(line_of(*surface_table.get("file")), "surface.file",
                 flag + " sets the points of a generated surface, and this scene's surface is read from " +
                     file->path.string() + ", whose grid is the file's",
                 "no --grid; to run on part of the file, surface.crop = " + std::string(kCropAccepted) +
                     " (docs/formats.md)");
    problems.throw_if_any();
  }
  const auto& generated = std::get<GeneratedSurfaceSpec>(as_written.surface.source);
  const toml::table& generate_table = *surface_table.get("generate")->as_table();
  const toml::node& grid_node = *generate_table.get("grid");
  // A qs the scene leaves out is the grid's Nyquist wavevector (surface.generate.qs), so it follows the grid.
  const bool qs_given = generate_table.contains("qs");
  const SelfAffinePsd psd{.sigma = generated.sigma,
                          .hurst = generated.hurst,
                          .qr = generated.qr,
                          .qs = qs_given ? generated.qs : std::nullopt,
                          .anisotropy = generated.anisotropy};
  if (const auto refusal = generator_refusal(psd, generated.size, points)) {
    const Index least = least_valid_points(psd, generated.size, generated.grid);
    problems.add(line_of(grid_node), "surface.generate.grid",
                 flag + " cannot carry this scene's spectrum (" + *refusal + ")",
                 "--grid " + std::to_string(least) + " or more (the least points a side that resolve " +
                     (qs_given ? "surface.generate.qs = " + exact_number(*generated.qs) + " 1/m"
                               : "surface.generate.qr = " + exact_number(generated.qr) +
                                     " 1/m below the grid's Nyquist wavevector") +
                     ")");
    problems.throw_if_any();
  }

  toml::table result = document;
  toml::table& generate = *result["surface"]["generate"].as_table();
  generate.insert_or_assign("grid", static_cast<std::int64_t>(points));
  // Every refine key the same ratio finer than the new grid as the scene's was than its own.
  const auto scale_refine = [&](toml::table& table, const std::string& path) {
    const auto* refine = table.get_as<std::int64_t>("refine");
    if (!refine || refine->get() <= 0) return;
    const Index scaled = scaled_points(static_cast<Index>(refine->get()), generated.grid, points);
    if (scaled > kMaxPointsASide)
      problems.add(line_of(*refine), path + ".refine",
                   flag + " scales refine = " + std::to_string(refine->get()) + " to " +
                       std::to_string(scaled) + " points a side (by " + std::to_string(points) + "/" +
                       std::to_string(generated.grid) + "), above the largest grid",
                   "--grid N with refine x N / " + std::to_string(generated.grid) +
                       " <= " + std::to_string(kMaxPointsASide));
    else
      table.insert_or_assign("refine", static_cast<std::int64_t>(scaled));
  };
  scale_refine(generate, "surface.generate");
  if (toml::table* methods = result["methods"].as_table())
    for (auto&& [label, node] : *methods)
      if (toml::table* method = node.as_table()) scale_refine(*method, "methods." + std::string(label.str()));
  problems.throw_if_any();

  // The report says so where a reader looks first: the scene's description (table.md, summary.json).
  const std::string note =
      "Run with " + flag + ": the surface generated on " + std::to_string(points) + " x " +
      std::to_string(points) + " points instead of the scene's " + std::to_string(generated.grid) + " x " +
      std::to_string(generated.grid) + (qs_given ? "" : " (qs at the new grid's Nyquist wavevector)") +
      ", every refine scaled by " + std::to_string(points) + "/" + std::to_string(generated.grid) + ".";
  result.insert_or_assign("description",
                          as_written.description.empty() ? note : as_written.description + " " + note);
  return result;
}

}  // namespace contactbench
