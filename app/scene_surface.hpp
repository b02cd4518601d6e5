// The scene's surface as its stages and methods see it: whole in this process, or, run as several MPI ranks
// with a generated surface, made slab by slab on the ranks (app/distributed_stages.hpp, docs/mpi.md) so
// that no rank holds it whole. Then this process keeps only what the preflights and theories read of it,
// reduced over the slabs (the grid, the moments, the heights' extremes), and gathers the whole heights the
// first time a method asks for them (a fit to the lattice spectrum, the plateau's mean gap): only then does
// rank 0 hold the whole surface.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

// What the ranks' slabs of a surface reduce to, with the way to gather it whole.
struct ResidentSurface {
  Grid grid;
  SpectralMoments moments;  // the slabs' spectral moments (distributed_spectral_moments)
  Real min_height = 0, max_height = 0;
  std::function<Surface()> gather;  // the whole surface on this process (collective with the ranks)
  // For each level z, the mean of (z - h)+ over the slabs (collective with the ranks).
  std::function<std::vector<Real>(const std::vector<Real>&)> mean_gaps;
};

class SceneSurface {
 public:
  explicit SceneSurface(Surface whole);
  explicit SceneSurface(ResidentSurface resident);

  const Grid& grid() const { return grid_; }
  // The heights live on the ranks' slabs (ResidentSurface); whole() gathers them.
  bool resident() const { return static_cast<bool>(resident_); }
  // The slabs' moments when resident; nothing otherwise (computed from the whole heights).
  std::optional<SpectralMoments> resident_moments() const;
  // Bytes of whole-surface heights this process holds: 0 while resident and never gathered.
  std::size_t whole_bytes() const;
  // max - min of the heights (exact from the slabs' extremes when resident).
  Real height_range() const;

  // For each level z [m] (NaN: none), the mean over the surface of (z - h)+: the undeformed gap below a flat
  // at z (docs/theory.md section 12.5); over the slabs when resident, so that it gathers nothing.
  std::vector<Real> mean_gaps(const std::vector<Real>& levels) const;

  // The whole surface here: gathered from the slabs on the first call when resident.
  const Surface& whole() const;
  operator const Surface&() const { return whole(); }  // NOLINT: the methods' reads of the whole surface
  const HeightMap& heights() const { return whole().heights(); }

 private:
  Grid grid_;
  std::shared_ptr<const ResidentSurface> resident_;
  mutable std::optional<Surface> whole_;
};

}  // namespace contactbench
