#include "contactbench/core/sweep.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/core/memory_budget.hpp"
#include "contactbench/core/stripe_components.hpp"
#include "contactbench/core/stripe_seams.hpp"
#include "contactbench/core/sweep_levels.hpp"

namespace contactbench {

using sweep_detail::ExcessReader;
using sweep_detail::ExcessStep;
using sweep_detail::fixed_levels;
using sweep_detail::joining_level;
using sweep_detail::JoinTime;
using sweep_detail::kNever;
using sweep_detail::LocalJoin;
using sweep_detail::SharedForest;
using sweep_detail::StripeComponents;
using sweep_detail::StripeReader;
using sweep_detail::StripeRecord;
using sweep_detail::StripeRows;
using sweep_detail::sweep_stripe_levels;

namespace {

// ---- Ordering points by join time ------------------------------------------------------------------------

// A double's bits as an unsigned key whose ascending order is the doubles' descending order
// (-0.0 is first made +0.0, so that equal heights always have equal keys).
JoinTime descending_key(Real height) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(height + 0.0);
  constexpr std::uint64_t kSign = std::uint64_t{1} << 63;
  return ~((bits & kSign) ? ~bits : bits | kSign);
}

Real height_of_key(JoinTime key) {
  constexpr std::uint64_t kSign = std::uint64_t{1} << 63;
  const std::uint64_t ascending = ~key;
  return std::bit_cast<Real>((ascending & kSign) ? ascending & ~kSign : ~ascending);
}

struct TimedPoint {
  JoinTime time;
  std::int32_t index;
};

// Stable LSD radix sort by time, 11 bits a pass, only over the bits in which the times differ.
void radix_sort(TimedPoint* points, TimedPoint* scratch, Index count) {
  if (count < 2) return;
  JoinTime low = points[0].time, high = points[0].time;
  for (Index i = 1; i < count; ++i) {
    low = std::min(low, points[i].time);
    high = std::max(high, points[i].time);
  }
  constexpr int kBits = 11;
  constexpr std::size_t kRadix = std::size_t{1} << kBits;
  const int width = std::bit_width(high - low);
  TimedPoint* from = points;
  TimedPoint* to = scratch;
  std::array<Index, kRadix + 1> starts;
  for (int shift = 0; shift < width; shift += kBits) {
    starts.fill(0);
    for (Index i = 0; i < count; ++i)
      ++starts[((from[i].time - low) >> shift) % kRadix + 1];
    std::partial_sum(starts.begin(), starts.end(), starts.begin());
    for (Index i = 0; i < count; ++i)
      to[starts[((from[i].time - low) >> shift) % kRadix]++] = from[i];
    std::swap(from, to);
  }
  if (from != points) std::copy(from, from + count, points);
}

// ---- Sweeping one stripe ---------------------------------------------------------------------------------

constexpr Index kPrefetchDistance = 16;

// Exact levels: the stripe's points in descending height (ties in index order), then one union-find pass
// with a record at every distinct height. The sort is a stable counting sort into 2048 buckets by a linear
// map of the height (monotone, even for any distribution of heights, and few enough write streams to stay
// in cache), then a radix sort of each bucket by the heights' keys.
void sweep_stripe_exact(const HeightMap& heights, Index first, Index last, StripeComponents& stripe) {
  const Real* h = heights.data();
  const Eigen::Map<const Eigen::ArrayXd> range(h + first, last - first);
  const Real top = range.maxCoeff(), bottom = range.minCoeff();
  constexpr Index kBuckets = 2048;
  const Real scale = top > bottom ? static_cast<Real>(kBuckets) / (top - bottom) : 0.0;
  auto bucket_of = [&](Index i) {
    return std::min<Index>(static_cast<Index>((top - h[i]) * scale), kBuckets - 1);
  };
  std::vector<Index> starts(kBuckets + 1, 0);
  for (Index i = first; i < last; ++i)
    ++starts[bucket_of(i) + 1];
  std::partial_sum(starts.begin(), starts.end(), starts.begin());
  std::vector<TimedPoint> order(static_cast<std::size_t>(last - first));
  std::vector<Index> next(starts.begin(), starts.end() - 1);
  for (Index i = first; i < last; ++i)
    order[next[bucket_of(i)]++] = {descending_key(h[i]), static_cast<std::int32_t>(i)};
  std::vector<TimedPoint> scratch;
  for (Index b = 0; b < kBuckets; ++b) {
    const Index size = starts[b + 1] - starts[b];
    if (size > 32) {
      scratch.resize(static_cast<std::size_t>(size));
      radix_sort(order.data() + starts[b], scratch.data(), size);
    } else {  // small buckets: insertion sort, stable
      for (Index i = starts[b] + 1; i < starts[b + 1]; ++i)
        for (Index k = i; k > starts[b] && order[k - 1].time > order[k].time; --k)
          std::swap(order[k - 1], order[k]);
    }
  }
  const Index count = static_cast<Index>(order.size());
  stripe.records().reserve(static_cast<std::size_t>(count));
  for (Index k = 0; k < count; ++k) {
    if (k + kPrefetchDistance < count) stripe.prefetch(order[k + kPrefetchDistance].index);
    if (k == 0 || order[k].time != order[k - 1].time) stripe.record(order[k].time);
    stripe.add(order[k].index, order[k].time);
  }
}

// Exact levels: a level at every distinct height, in order, merging the stripes' records by time. At the
// level of time t, {h > z} holds the times < t: each stripe's state is the one before its first record with
// time >= t, i.e. its current record (or its final state once its records are used up). The time range is
// cut in two at a median time and the halves are merged by two threads into disjoint parts of the output
// (a part may hold fewer levels than its bound when stripes share a height; the gap is closed afterwards).
void merge_exact_levels(std::vector<StripeComponents>& stripes, const std::vector<ExcessStep>& excess_steps,
                        Index n, int team, SweepCurve& curve) {
  const std::size_t stripe_count = stripes.size();
  std::size_t bound = 0;
  for (auto& stripe : stripes)
    bound += stripe.records().size();
  // Split time: the median record time of the largest stripe (any time works; a median balances the halves).
  JoinTime split = kNever;
  for (auto& stripe : stripes)
    if (!stripe.records().empty() && (split == kNever || stripe.records().size() * 2 > bound))
      split = stripe.records()[stripe.records().size() / 2].time;
  const int parts = team_size(static_cast<Index>(bound), team) > 1 ? 2 : 1;
  // Each part: where it starts in every stripe's records and in the output.
  std::vector<std::vector<std::size_t>> start(parts + 1, std::vector<std::size_t>(stripe_count, 0));
  for (std::size_t s = 0; s < stripe_count; ++s) {
    const auto& records = stripes[s].records();
    start[parts][s] = records.size();
    if (parts == 2)
      start[1][s] = static_cast<std::size_t>(
          std::lower_bound(records.begin(), records.end(), split,
                           [](const StripeRecord& r, JoinTime t) { return r.time < t; }) -
          records.begin());
  }
  std::vector<std::size_t> output_start(parts + 1, 0);
  for (int p = 0; p <= parts; ++p)
    for (std::size_t s = 0; s < stripe_count; ++s)
      output_start[p] += start[p][s];

      // Sized by several threads at once, so that the first touch of the pages is shared too.
#pragma omp parallel sections num_threads(parts)
  {
#pragma omp section
    {
      curve.z.resize(bound);
      curve.points.resize(bound);
    }
#pragma omp section
    {
      curve.spots.resize(bound);
      curve.area_fraction.resize(bound);
    }
  }
  std::vector<std::size_t> written(parts, 0);
  const Real points_total = static_cast<Real>(n);
#pragma omp parallel for num_threads(parts) schedule(static, 1)
  for (int p = 0; p < parts; ++p) {
    std::vector<std::size_t> position = start[p];
    const std::size_t first_excess = static_cast<std::size_t>(
        std::upper_bound(excess_steps.begin(), excess_steps.end(), p == 0 ? JoinTime{0} : split - 1,
                         [](JoinTime t, const ExcessStep& e) { return t < e.time; }) -
        excess_steps.begin());
    ExcessReader excess(excess_steps, p == 0 ? 0 : first_excess);
    std::size_t out = output_start[p];
    for (;;) {
      JoinTime next = kNever;
      Index components = 0, points = 0;
      for (std::size_t s = 0; s < stripe_count; ++s) {
        const auto& records = stripes[s].records();
        if (position[s] < records.size()) {
          const StripeRecord& record = records[position[s]];
          if (position[s] < start[p + 1][s]) next = std::min(next, record.time);
          components += record.components_before;
          points += record.points_before;
        } else {
          components += stripes[s].components();
          points += stripes[s].points();
        }
      }
      if (next == kNever) break;
      curve.z[out] = height_of_key(next);
      curve.points[out] = points;
      curve.spots[out] = components - excess.at(next - 1);
      curve.area_fraction[out] = static_cast<Real>(points) / points_total;
      ++out;
      for (std::size_t s = 0; s < stripe_count; ++s)
        if (position[s] < start[p + 1][s] && stripes[s].records()[position[s]].time == next) ++position[s];
    }
    written[p] = out - output_start[p];
  }
  // Close the gaps left where stripes shared a height.
  std::size_t end = written[0];
  for (int p = 1; p < parts; ++p) {
    if (output_start[p] != end) {
      const auto from = static_cast<std::ptrdiff_t>(output_start[p]), to = static_cast<std::ptrdiff_t>(end);
      const auto count = static_cast<std::ptrdiff_t>(written[p]);
      std::copy(curve.z.begin() + from, curve.z.begin() + from + count, curve.z.begin() + to);
      std::copy(curve.points.begin() + from, curve.points.begin() + from + count, curve.points.begin() + to);
      std::copy(curve.spots.begin() + from, curve.spots.begin() + from + count, curve.spots.begin() + to);
      std::copy(curve.area_fraction.begin() + from, curve.area_fraction.begin() + from + count,
                curve.area_fraction.begin() + to);
    }
    end += written[p];
  }
  curve.z.resize(end);
  curve.points.resize(end);
  curve.spots.resize(end);
  curve.area_fraction.resize(end);
}

}  // namespace

std::uintmax_t sweep_memory_bytes(Index points, const SweepLevels& levels, int threads) {
  const auto n = static_cast<std::uintmax_t>(std::max<Index>(points, 0));
  if (levels.kind == SweepLevels::Kind::exact) return saturating_product(n, 8 + 16 + 24 + 32);
  const auto stripes = static_cast<std::uintmax_t>(std::max(threads, 1));
  const auto count = saturating_sum(static_cast<std::uintmax_t>(std::max<Index>(levels.count, 0)), 2);
  return saturating_sum(saturating_product(n, 8 + 4),
                        saturating_product(count, saturating_sum(8 + 32, saturating_product(stripes, 32))));
}

SweepCurve sweep(const Surface& surface, const SweepLevels& levels, const Topology& topology, int threads) {
  const HeightMap& heights = surface.heights();
  const Index nx = surface.nx(), ny = surface.ny(), n = heights.size();
  if (n >= SharedForest::kMaxPoints)
    throw Error("sweep: " + std::to_string(n) + " points are more than the sweep's limit of 2^30");
  check_fits_in_memory(
      sweep_memory_bytes(n, levels, threads),
      "the sweep of " + std::to_string(n) + " points" +
          (levels.kind == SweepLevels::Kind::exact ? std::string(" at every distinct height")
                                                   : " at " + std::to_string(levels.count) + " levels"));
  const bool exact = levels.kind == SweepLevels::Kind::exact;
  // Fixed levels: from the highest height down to the lowest, or (paper) to the mean plane.
  const std::vector<Real> fixed_z =
      exact ? std::vector<Real>{}
            : fixed_levels(heights.maxCoeff(),
                           levels.kind == SweepLevels::Kind::paper ? heights.mean() : heights.minCoeff(),
                           levels.count);
  const int team = team_size(n, threads);

  // When a point joins {h > z}: its height's descending key (exact) or its level index (kNever: never).
  const Real* h = heights.data();
  auto time_of = [&](Index i) { return exact ? descending_key(h[i]) : joining_level(h[i], fixed_z); };

  // Horizontal stripes, one per thread (as many as asked, whatever the size, so that the joining logic is
  // the same for all sizes); each is swept on its own with its own part of one union-find array.
  const Index stripe_count = std::clamp<Index>(threads, 1, ny);
  std::vector<StripeRows> rows(static_cast<std::size_t>(stripe_count));
  for (Index s = 0; s < stripe_count; ++s)
    rows[s] = {s * ny / stripe_count, (s + 1) * ny / stripe_count};
  const bool seams = stripe_count > 1;
  SharedForest forest(n, seams);
  std::vector<StripeComponents> stripes;
  for (Index s = 0; s < stripe_count; ++s)
    stripes.emplace_back(forest, nx, ny, rows[s].begin, rows[s].end, topology,
                         seams && (s > 0 || topology.wrap_y),
                         seams && (s + 1 < stripe_count || topology.wrap_y));

#pragma omp parallel for num_threads(std::min <int>(team, static_cast <int>(stripe_count))) \
    schedule(static, 1)
  for (Index s = 0; s < stripe_count; ++s) {
    const Index first = rows[s].begin * nx, last = rows[s].end * nx;
    if (exact)
      sweep_stripe_exact(heights, first, last, stripes[s]);
    else
      sweep_stripe_levels(heights, fixed_z, first, last, stripes[s]);
  }

  std::vector<std::vector<LocalJoin>> local_joins;
  for (auto& stripe : stripes)
    local_joins.push_back(std::move(stripe.local_joins()));
  const std::vector<ExcessStep> excess_steps = seam_excess(local_joins, rows, topology, nx, ny, time_of);

  // The global curve: at each level, the stripes' counts less the components they counted twice.
  SweepCurve curve;
  curve.topology = topology;
  curve.levels = levels;
  curve.nominal_area = surface.grid().nominal_area();
  const Real points_total = static_cast<Real>(n);
  if (exact) {
    merge_exact_levels(stripes, excess_steps, n, team, curve);
  } else {
    ExcessReader excess(excess_steps, 0);
    std::vector<StripeReader> readers;
    for (auto& stripe : stripes)
      readers.emplace_back(stripe.records(), stripe.components(), stripe.points());
    for (std::size_t k = 0; k < fixed_z.size(); ++k) {
      Index components = 0, points = 0;
      for (StripeReader& reader : readers) {
        reader.advance(k);
        components += reader.components();
        points += reader.points();
      }
      curve.z.push_back(fixed_z[k]);
      curve.points.push_back(points);
      curve.spots.push_back(components - excess.at(k));
      curve.area_fraction.push_back(static_cast<Real>(points) / points_total);
    }
  }
  return curve;
}

}  // namespace contactbench
