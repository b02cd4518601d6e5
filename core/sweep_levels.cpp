#include "contactbench/core/sweep_levels.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "contactbench/core/error.hpp"

namespace contactbench::sweep_detail {

std::vector<Real> fixed_levels(Real top, Real bottom, Index count) {
  if (count < 1) throw Error("sweep: the number of levels must be at least 1, got " + std::to_string(count));
  std::vector<Real> z(static_cast<std::size_t>(count) + 1);
  const Real step = (top - bottom) / static_cast<Real>(count);
  for (Index k = 0; k <= count; ++k)
    z[k] = top - static_cast<Real>(k) * step;
  z.back() = bottom;
  return z;
}

SweepCurve empty_sweep_curve(const Grid& grid, const SweepLevels& levels, const Topology& topology) {
  SweepCurve curve;
  curve.topology = topology;
  curve.levels = levels;
  curve.nominal_area = grid.nominal_area();
  return curve;
}

void append_level(SweepCurve& curve, Real z, Index points, Index spots, Index total_points) {
  curve.z.push_back(z);
  curve.points.push_back(points);
  curve.spots.push_back(spots);
  curve.area_fraction.push_back(static_cast<Real>(points) / static_cast<Real>(total_points));
}

// A guess from the spacing, corrected against the stored levels so that h > z[k] holds exactly as reported.
JoinTime joining_level(Real height, const std::vector<Real>& z) {
  const Index levels = static_cast<Index>(z.size());
  if (!(height > z.back())) return kNever;
  const Real step = (z.front() - z.back()) / static_cast<Real>(levels - 1);
  Index k =
      step > 0 ? std::clamp<Index>(static_cast<Index>((z.front() - height) / step) + 1, 0, levels - 1) : 0;
  while (k > 0 && height > z[k - 1])
    --k;
  while (!(height > z[k]))
    ++k;
  return static_cast<JoinTime>(k);
}

// Points of one level stay in memory order, which the union-find pass then walks with good locality.
void sweep_stripe_levels(const HeightMap& heights, const std::vector<Real>& z, Index first, Index last,
                         StripeComponents& stripe) {
  const Real* h = heights.data();
  const Index levels = static_cast<Index>(z.size());
  std::vector<std::int32_t> level(static_cast<std::size_t>(last - first));
  std::vector<Index> starts(static_cast<std::size_t>(levels) + 2, 0);
  for (Index i = first; i < last; ++i) {
    const JoinTime t = joining_level(h[i], z);
    level[i - first] = t == kNever ? static_cast<std::int32_t>(levels) : static_cast<std::int32_t>(t);
    ++starts[level[i - first] + 1];
  }
  std::partial_sum(starts.begin(), starts.end(), starts.begin());
  std::vector<std::int32_t> order(static_cast<std::size_t>(starts[levels]));
  std::vector<Index> next(starts.begin(), starts.end() - 1);
  for (Index i = first; i < last; ++i)
    if (level[i - first] < levels) order[next[level[i - first]]++] = static_cast<std::int32_t>(i);
  const Index count = static_cast<Index>(order.size());
  for (Index k = 0, l = 0; l < levels; ++l) {
    if (starts[l] == starts[l + 1]) continue;
    stripe.record(static_cast<JoinTime>(l));
    for (; k < starts[l + 1]; ++k) {
      if (k + kPrefetchDistance < count) stripe.prefetch(order[k + kPrefetchDistance]);
      stripe.add(order[k], static_cast<JoinTime>(l));
    }
  }
}

}  // namespace contactbench::sweep_detail
