#include "contactbench/core/stripe_components.hpp"

#include <algorithm>
#include <utility>

namespace contactbench::sweep_detail {

SharedForest::SharedForest(Index points, bool track_seams) : parent_(static_cast<std::size_t>(points)) {
  std::fill(parent_.data(), parent_.data() + points, kAbsent);
  if (track_seams) representative_.resize(static_cast<std::size_t>(points));
}

StripeComponents::StripeComponents(SharedForest& forest, Index nx, Index ny, Index row_begin, Index row_end,
                                   const Topology& topology, bool seam_row_above, bool seam_row_below)
    : parent_(forest.parent()),
      representative_(forest.seam_representative()),
      nx_(nx),
      ny_(ny),
      row_begin_(row_begin),
      row_end_(row_end),
      inverse_nx_(1.0 / static_cast<double>(nx)),
      topology_(topology),
      wrap_y_inside_(topology.wrap_y && row_begin == 0 && row_end == ny),
      seam_row_above_(seam_row_above),
      seam_row_below_(seam_row_below),
      eight_(topology.connectivity == Connectivity::eight) {
  for (Index dy = -1; dy <= 1; ++dy)
    for (Index dx = -1; dx <= 1; ++dx)
      if ((dx != 0 || dy != 0) && (eight_ || dx == 0 || dy == 0)) {
        offsets_[steps_.size()] = dy * nx + dx;
        steps_.push_back({dx, dy});
      }
}

void StripeComponents::prefetch(std::int32_t i) const {
  // Points come in height order, scattered over the stripe: fetching the neighbourhood of a point a few
  // places ahead lets its cache misses overlap with the work on the current one.
  __builtin_prefetch(parent_ + i);
  if (i >= nx_) __builtin_prefetch(parent_ + i - nx_);
  if (i + nx_ < nx_ * ny_) __builtin_prefetch(parent_ + i + nx_);
}

std::int32_t StripeComponents::find(std::int32_t i) {
  while (parent_[i] >= 0) {
    const std::int32_t up = parent_[i];
    if (parent_[up] >= 0) parent_[i] = parent_[up];  // path halving
    i = up;
  }
  return i;
}

// Joins two different roots, the smaller under the larger; records the merge when both touch a seam.
std::int32_t StripeComponents::link(std::int32_t a, std::int32_t b, JoinTime time) {
  constexpr std::int32_t flag = SharedForest::kSeamFlag;
  const std::int32_t magnitude_a = -parent_[a], magnitude_b = -parent_[b];
  if ((magnitude_a & ~flag) < (magnitude_b & ~flag)) return link(b, a, time);
  if (magnitude_a & magnitude_b & flag)
    local_joins_.push_back({time, representative_[a], representative_[b]});
  else if (magnitude_b & flag)
    representative_[a] = representative_[b];
  parent_[a] = -(((magnitude_a & ~flag) + (magnitude_b & ~flag)) | ((magnitude_a | magnitude_b) & flag));
  parent_[b] = a;
  return a;
}

template <int kNeighbours>
void StripeComponents::add(std::int32_t i, JoinTime time) {
  // Row and column without an integer division (tens of cycles): a floating-point reciprocal, corrected.
  Index y = static_cast<Index>(static_cast<double>(i) * inverse_nx_);
  if (y * nx_ > i) --y;
  if ((y + 1) * nx_ <= i) ++y;
  const Index x = i - y * nx_;

  std::int32_t root = -1;  // the root i joins, once a present neighbour is found
  auto visit = [&](std::int32_t j) {
    const std::int32_t entry = parent_[j];
    if (entry == SharedForest::kAbsent) return;
    if (root < 0) {
      root = find(j);
    } else if (j != root && entry != root) {  // a direct child of root needs no search
      const std::int32_t other = find(j);
      if (other != root) {
        root = link(root, other, time);
        --components_;
      }
    }
  };
  if (x > 0 && x + 1 < nx_ && y > row_begin_ && y + 1 < row_end_) {
    for (const Index offset : offsets_)
      visit(static_cast<std::int32_t>(i + offset));
  } else {
    // On tiny periodic grids a neighbour may coincide with another or with the point itself (not yet
    // present); uniting twice changes nothing.
    for (const auto& [dx, dy] : steps_) {
      Index xn = x + dx, yn = y + dy;
      if (xn < 0 || xn >= nx_) {
        if (!topology_.wrap_x) continue;
        xn = (xn + nx_) % nx_;
      }
      if (yn < row_begin_ || yn >= row_end_) {
        if (!wrap_y_inside_) continue;
        yn = (yn + ny_) % ny_;
      }
      visit(static_cast<std::int32_t>(yn * nx_ + xn));
    }
  }

  const bool seam = is_seam_row(y);
  constexpr std::int32_t flag = SharedForest::kSeamFlag;
  ++points_;
  if (root < 0) {
    parent_[i] = seam ? -(1 | flag) : -1;
    if (seam) representative_[i] = i;
    ++components_;
    return;
  }
  parent_[i] = root;
  --parent_[root];  // one more point (sizes are stored negated)
  if (!seam) return;
  if (-parent_[root] & flag) {
    local_joins_.push_back({time, representative_[root], i});
  } else {
    parent_[root] = -(-parent_[root] | flag);
    representative_[root] = i;
  }
}

template void StripeComponents::add<4>(std::int32_t, JoinTime);
template void StripeComponents::add<8>(std::int32_t, JoinTime);

}  // namespace contactbench::sweep_detail
