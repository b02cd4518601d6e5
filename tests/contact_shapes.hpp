// Surfaces with analytic contact solutions, shared by the BEM tests (docs/theory.md section 7).
#pragma once

#include <cmath>
#include <numbers>

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

// Westergaard's wavy surface h = D cos(2 pi s/lambda) over one wavelength of n points, along x (n x m
// points) or along y (m x n points): the same problem on a grid and on its transpose.
inline Surface wavy(Index n, Index m, bool along_y, Real lambda, Real amplitude) {
  const Real width = lambda * static_cast<Real>(m) / static_cast<Real>(n);
  const Grid grid{.nx = along_y ? m : n,
                  .ny = along_y ? n : m,
                  .lx = along_y ? width : lambda,
                  .ly = along_y ? lambda : width,
                  .periodic = true};
  HeightMap h(grid.ny, grid.nx);
  for (Index iy = 0; iy < grid.ny; ++iy)
    for (Index ix = 0; ix < grid.nx; ++ix)
      h(iy, ix) = amplitude * std::cos(2 * std::numbers::pi * (along_y ? iy : ix) / static_cast<Real>(n));
  return Surface(grid, h);
}

// The same cap on an n x n grid.
inline Surface sphere(Index n, Real dx, Real radius) {
  return sphere_cap(n, n, dx, radius);
}

}  // namespace contactbench
