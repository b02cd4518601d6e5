// Internal to the sweep (core/sweep.cpp) and its distributed version (mpi/): the fixed levels of a sweep,
// when a height joins {h > z}, sweeping one stripe at fixed levels, and reading a stripe's state per level
// (docs/theory.md section 3).
#pragma once

#include <vector>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/stripe_components.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/core/sweep_exact.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench::sweep_detail {

// count + 1 levels from `top` down to `bottom`, equally spaced, the last exactly `bottom` (count >= 1, else
// Error).
std::vector<Real> fixed_levels(Real top, Real bottom, Index count);

// The level at which a point of this height joins: the first with z[k] < height (kNever: none).
JoinTime joining_level(Real height, const std::vector<Real>& z);

// When a point of this height joins {h > z}: its height's descending key at every distinct height (exact),
// else its level among the fixed levels z.
inline JoinTime join_time(Real height, bool exact, const std::vector<Real>& z) {
  return exact ? descending_key(height) : joining_level(height, z);
}

// The sweep's curve before its rows: what it was swept with, and A0.
SweepCurve empty_sweep_curve(const Grid& grid, const SweepLevels& levels, const Topology& topology);

// Appends the row of the fixed level z: `points` of the grid's `total_points` above it, in `spots` spots.
void append_level(SweepCurve& curve, Real z, Index points, Index spots, Index total_points);

// Sweeps the points [first, last) of `heights` (row-major, the stripe's grid) at the levels z into `stripe`:
// a stable counting sort by joining level, then the union-find pass with a record at each level.
void sweep_stripe_levels(const HeightMap& heights, const std::vector<Real>& z, Index first, Index last,
                         StripeComponents& stripe);

// A stripe's state after every point with time <= t: the counts before its first record with time > t.
class StripeReader {
 public:
  StripeReader(const std::vector<StripeRecord>& records, Index final_components, Index final_points)
      : records_(records), final_components_(final_components), final_points_(final_points) {}
  void advance(JoinTime t) {
    while (next_ < records_.size() && records_[next_].time <= t)
      ++next_;
  }
  Index components() const {
    return next_ < records_.size() ? records_[next_].components_before : final_components_;
  }
  Index points() const { return next_ < records_.size() ? records_[next_].points_before : final_points_; }

 private:
  const std::vector<StripeRecord>& records_;
  Index final_components_, final_points_;
  std::size_t next_ = 0;
};

}  // namespace contactbench::sweep_detail
