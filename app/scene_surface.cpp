#include "contactbench/app/scene_surface.hpp"

#include <cmath>
#include <utility>

namespace contactbench {

SceneSurface::SceneSurface(Surface whole) : grid_(whole.grid()), whole_(std::move(whole)) {}

SceneSurface::SceneSurface(ResidentSurface resident)
    : grid_(resident.grid), resident_(std::make_shared<const ResidentSurface>(std::move(resident))) {}

std::optional<SpectralMoments> SceneSurface::resident_moments() const {
  if (!resident_) return std::nullopt;
  return resident_->moments;
}

std::size_t SceneSurface::whole_bytes() const {
  return whole_ ? static_cast<std::size_t>(whole_->heights().size()) * sizeof(Real) : 0;
}

Real SceneSurface::height_range() const {
  if (resident_ && !whole_) return resident_->max_height - resident_->min_height;
  const HeightMap& h = whole_->heights();
  return h.size() ? h.maxCoeff() - h.minCoeff() : 0;
}

std::vector<Real> SceneSurface::mean_gaps(const std::vector<Real>& levels) const {
  if (resident_ && !whole_) return resident_->mean_gaps(levels);
  const HeightMap& h = whole_->heights();
  std::vector<Real> gaps;
  for (const Real z : levels)
    gaps.push_back(std::isfinite(z) ? (z - h).max(0.0).mean() : std::nan(""));
  return gaps;
}

const Surface& SceneSurface::whole() const {
  if (!whole_) whole_ = resident_->gather();
  return *whole_;
}

}  // namespace contactbench
