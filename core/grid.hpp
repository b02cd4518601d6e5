// The sampling lattice of a surface: point counts, lateral sizes and periodicity.
#pragma once

#include <algorithm>
#include <numbers>

#include "contactbench/core/types.hpp"

namespace contactbench {

struct Grid {
  Index nx = 0;           // points along x (columns)
  Index ny = 0;           // points along y (rows)
  Real lx = 0;            // lateral size along x [m]
  Real ly = 0;            // lateral size along y [m]
  bool periodic = false;  // does the surface repeat with periods lx, ly?

  Real dx() const { return lx / static_cast<Real>(nx); }
  Real dy() const { return ly / static_cast<Real>(ny); }
  Index points() const { return nx * ny; }
  Real nominal_area() const { return lx * ly; }  // A0 (docs/theory.md section 0)
  // Lattice spacing of the wavevectors, q_k = 2 pi (kx/Lx, ky/Ly) (docs/theory.md section 1).
  Real dqx() const { return 2 * std::numbers::pi / lx; }
  Real dqy() const { return 2 * std::numbers::pi / ly; }
  // Largest wavevector both axes resolve: the radius of the circle that fits in the lattice.
  Real nyquist() const { return std::numbers::pi / std::max(dx(), dy()); }
};

// Throws Error unless nx, ny >= 1 and lx, ly are finite and > 0; `what` names the caller's context.
void validate(const Grid& grid, const char* what = "grid");

}  // namespace contactbench
