// Surfaces with analytic contact solutions, shared by the BEM tests (docs/theory.md section 7).
#pragma once

#include "contactbench/core/surface.hpp"

namespace contactbench {

// The paraboloidal cap h = -r^2/(2R) of a sphere of radius R, centred on node (nx/2, ny/2) of a non-periodic
// grid of square pixels dx.
inline Surface sphere_cap(Index nx, Index ny, Real dx, Real radius) {
  const Grid grid{.nx = nx, .ny = ny, .lx = nx * dx, .ly = ny * dx, .periodic = false};
  HeightMap h(ny, nx);
  for (Index iy = 0; iy < ny; ++iy)
    for (Index ix = 0; ix < nx; ++ix) {
      const Real x = (ix - nx / 2) * dx, y = (iy - ny / 2) * dx;
      h(iy, ix) = -(x * x + y * y) / (2 * radius);
    }
  return Surface(grid, h);
}

// The same cap on an n x n grid.
inline Surface sphere(Index n, Real dx, Real radius) {
  return sphere_cap(n, n, dx, radius);
}

}  // namespace contactbench
