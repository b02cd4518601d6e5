#include "contactbench/app/mirrored_boundary.hpp"

namespace contactbench {

Grid mirrored_grid(const Grid& patch) {
  return Grid{
      .nx = 2 * patch.nx, .ny = 2 * patch.ny, .lx = 2 * patch.lx, .ly = 2 * patch.ly, .periodic = true};
}

Surface mirrored_surface(const Surface& patch) {
  const Grid& grid = patch.grid();
  const Index nx = grid.nx, ny = grid.ny;
  const HeightMap& h = patch.heights();
  HeightMap extended(2 * ny, 2 * nx);
  extended.block(0, 0, ny, nx) = h;
  extended.block(0, nx, ny, nx) = h.rowwise().reverse();
  extended.block(ny, 0, ny, nx) = h.colwise().reverse();
  extended.block(ny, nx, ny, nx) = h.reverse();
  return Surface(mirrored_grid(grid), std::move(extended));
}

ContactSolution patch_of(const ContactSolution& mirrored, Index nx, Index ny, std::optional<Real> hardness) {
  ContactSolution patch = mirrored;
  patch.pressure = mirrored.pressure.block(0, 0, ny, nx);
  patch.gap = mirrored.gap.block(0, 0, ny, nx);
  if (mirrored.plastic_overlap.size() > 0)
    patch.plastic_overlap = mirrored.plastic_overlap.block(0, 0, ny, nx);
  patch.plastic_points = hardness ? (patch.pressure.array() >= *hardness).count() : 0;
  patch.contact_points = (patch.pressure.array() > 0).count();
  patch.mean_pressure = patch.pressure.mean();
  return patch;
}

}  // namespace contactbench
