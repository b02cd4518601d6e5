#include "contactbench/core/sweep_exact.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <numeric>

#include <Eigen/Core>

namespace contactbench::sweep_detail {

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

namespace {

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

}  // namespace

// A stable counting sort into 2048 buckets by a linear map of the height (monotone, even for any distribution
// of heights, and few enough write streams to stay in cache), then a radix sort of each bucket by the
// heights' keys; then one union-find pass with a record at every distinct height.
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

// The time range is cut in two at a median time and the halves are merged by two threads into disjoint parts
// of the output (a part may hold fewer levels than its bound when stripes share a height; the gap is closed
// afterwards).
void merge_exact_levels(const std::vector<StripeHistory>& stripes,
                        const std::vector<ExcessStep>& excess_steps, Index n, int team, SweepCurve& curve) {
  const std::size_t stripe_count = stripes.size();
  std::size_t bound = 0;
  for (const auto& stripe : stripes)
    bound += stripe.records.size();
  // Split time: the median record time of the largest stripe (any time works; a median balances the halves).
  JoinTime split = kNever;
  for (const auto& stripe : stripes)
    if (!stripe.records.empty() && (split == kNever || stripe.records.size() * 2 > bound))
      split = stripe.records[stripe.records.size() / 2].time;
  const int parts = team_size(static_cast<Index>(bound), team) > 1 ? 2 : 1;
  // Each part: where it starts in every stripe's records and in the output.
  std::vector<std::vector<std::size_t>> start(parts + 1, std::vector<std::size_t>(stripe_count, 0));
  for (std::size_t s = 0; s < stripe_count; ++s) {
    const auto& records = stripes[s].records;
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
        const auto& records = stripes[s].records;
        if (position[s] < records.size()) {
          const StripeRecord& record = records[position[s]];
          if (position[s] < start[p + 1][s]) next = std::min(next, record.time);
          components += record.components_before;
          points += record.points_before;
        } else {
          components += stripes[s].components;
          points += stripes[s].points;
        }
      }
      if (next == kNever) break;
      curve.z[out] = height_of_key(next);
      curve.points[out] = points;
      curve.spots[out] = components - excess.at(next - 1);
      curve.area_fraction[out] = static_cast<Real>(points) / points_total;
      ++out;
      for (std::size_t s = 0; s < stripe_count; ++s)
        if (position[s] < start[p + 1][s] && stripes[s].records[position[s]].time == next) ++position[s];
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

}  // namespace contactbench::sweep_detail
