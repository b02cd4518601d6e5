#include "contactbench/core/surface.hpp"

#include <cmath>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench {

void validate(const Grid& grid, const char* what) {
  const std::string name(what);
  if (grid.nx < 1 || grid.ny < 1)
    throw Error(name + ": needs at least one point along x and y, got " + std::to_string(grid.nx) + " x " +
                std::to_string(grid.ny));
  if (!(std::isfinite(grid.lx) && grid.lx > 0) || !(std::isfinite(grid.ly) && grid.ly > 0))
    throw Error(name + ": lateral sizes must be finite and > 0 m, got lx = " + formats::format_real(grid.lx) +
                ", ly = " + formats::format_real(grid.ly));
}

Surface::Surface(Grid grid, HeightMap heights) : grid_(grid), heights_(std::move(heights)) {
  validate(grid_, "surface");
  if (heights_.rows() != grid_.ny || heights_.cols() != grid_.nx)
    throw Error("surface: height array is " + std::to_string(heights_.cols()) + " x " +
                std::to_string(heights_.rows()) + " (x by y) but the grid is " + std::to_string(grid_.nx) +
                " x " + std::to_string(grid_.ny));
  // One plain pass: Eigen's allFinite() computes (h - h) == (h - h) coefficient by coefficient, which made
  // this check the largest single cost of reading a 4096^2 file (results/bench/formats_read.md).
  bool finite = true;
  const Real* h = heights_.data();
  for (Index k = 0; k < heights_.size(); ++k)
    finite &= std::isfinite(h[k]);
  if (!finite) {
    for (Index iy = 0; iy < heights_.rows(); ++iy)
      for (Index ix = 0; ix < heights_.cols(); ++ix)
        if (!std::isfinite(heights_(iy, ix)))
          throw Error("surface: height at (ix, iy) = (" + std::to_string(ix) + ", " + std::to_string(iy) +
                      ") is not finite");
  }
}

Real Surface::rms_height() const {
  return std::sqrt((heights_ - heights_.mean()).square().mean());
}

Surface Surface::centred() const {
  return Surface(grid_, heights_ - heights_.mean());
}

Surface Surface::with_periodic(bool periodic) const {
  Grid grid = grid_;
  grid.periodic = periodic;
  return Surface(grid, heights_);
}

}  // namespace contactbench
