// Internal to the sweep (core/sweep.cpp): the connected components of the points added so far within one
// horizontal stripe of the grid, grown point by point with a union-find, and a record of every merge that
// joins two components touching the stripe's seam rows, so that stripes swept in parallel can be joined
// afterwards (docs/theory.md section 3).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "contactbench/core/large_buffer.hpp"
#include "contactbench/core/topology.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench::sweep_detail {

// When a point joins: a level index, or a height's descending key (smaller = earlier). kNever: it never does.
using JoinTime = std::uint64_t;
inline constexpr JoinTime kNever = std::numeric_limits<JoinTime>::max();

// Seam points a and b became connected within their stripe at `time` (or b joined a's component).
struct LocalJoin {
  JoinTime time;
  std::int32_t a, b;
};

// The stripe's state just before the first point with this join time was added.
struct StripeRecord {
  JoinTime time;
  std::int32_t components_before;
  std::int32_t points_before;
};

// The whole grid's union-find array, shared by the stripes (each touches only its own rows). Entries:
// kAbsent for a point not yet added; for a root, -(size | kSeamFlag if its component touches a seam row);
// otherwise the parent's index. One array keeps every look-up to one cache miss.
class SharedForest {
 public:
  static constexpr std::int32_t kAbsent = std::numeric_limits<std::int32_t>::max();
  static constexpr std::int32_t kSeamFlag = std::int32_t{1} << 30;
  static constexpr Index kMaxPoints = Index{1} << 30;  // sizes must stay below the flag bit

  SharedForest(Index points, bool track_seams);
  std::int32_t* parent() { return parent_.data(); }
  std::int32_t* seam_representative() { return representative_.data(); }

 private:
  LargeBuffer<std::int32_t> parent_;
  LargeBuffer<std::int32_t> representative_;  // for flagged roots: one seam point of the component
};

class StripeComponents {
 public:
  // Rows [row_begin, row_end) of an nx x ny grid. The stripe wraps in y only when it is the whole grid.
  // `seam_row_above` / `seam_row_below`: whether the stripe's first / last row borders another stripe.
  StripeComponents(SharedForest& forest, Index nx, Index ny, Index row_begin, Index row_end,
                   const Topology& topology, bool seam_row_above, bool seam_row_below);

  void prefetch(std::int32_t i) const;
  void add(std::int32_t i, JoinTime time) {
    if (eight_)
      add<8>(i, time);
    else
      add<4>(i, time);
  }

  // Called before the first point of each new join time, to record the stripe's state.
  void record(JoinTime time) {
    records_.push_back({time, static_cast<std::int32_t>(components_), static_cast<std::int32_t>(points_)});
  }
  Index components() const { return components_; }
  Index points() const { return points_; }
  std::vector<StripeRecord>& records() { return records_; }
  std::vector<LocalJoin>& local_joins() { return local_joins_; }

 private:
  template <int kNeighbours>
  void add(std::int32_t i, JoinTime time);
  std::int32_t find(std::int32_t i);
  std::int32_t link(std::int32_t a, std::int32_t b, JoinTime time);
  bool is_seam_row(Index y) const {
    return (seam_row_above_ && y == row_begin_) || (seam_row_below_ && y + 1 == row_end_);
  }

  std::int32_t* parent_;
  std::int32_t* representative_;
  Index nx_, ny_, row_begin_, row_end_;
  double inverse_nx_;
  Topology topology_;
  bool wrap_y_inside_;
  bool seam_row_above_, seam_row_below_;
  bool eight_;
  std::vector<std::pair<Index, Index>> steps_;  // (dx, dy) of the neighbours
  std::array<Index, 8> offsets_{};              // the same as index offsets, for interior points
  Index components_ = 0, points_ = 0;
  std::vector<StripeRecord> records_;
  std::vector<LocalJoin> local_joins_;
};

}  // namespace contactbench::sweep_detail
