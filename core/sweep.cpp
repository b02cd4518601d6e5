#include "core/sweep.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/large_buffer.hpp"

namespace contactbench {

namespace {

// The order in which points join {h > z} as z falls, and the levels at which the state is recorded:
// the set {h > z[j]} is exactly the first `joined[j]` points of `order`.
struct JoinSchedule {
  std::vector<std::int32_t> order;
  std::vector<Real> z;
  std::vector<Index> joined;
};

// Stable counting sort of the points by bucket (0 first), in parallel: each thread counts and scatters its
// own contiguous share of the points, and shares are laid out in thread order, so the result is the same for
// any thread count. out[...] = item(i) for every point i whose bucket is below bucket_count (the others are
// dropped). Returns the bucket starts in `out` (bucket_count + 1 entries).
template <typename Item, typename MakeItem>
std::vector<Index> bucket_points(const std::vector<std::int32_t>& bucket_of, Index bucket_count,
                                 std::vector<Item>& out, int threads, MakeItem&& item) {
  const Index n = static_cast<Index>(bucket_of.size());
  const int shares = std::max(1, threads);
  std::vector<std::vector<Index>> next(shares, std::vector<Index>(bucket_count + 1, 0));
  auto share_begin = [&](int t) { return n * t / shares; };
#pragma omp parallel for num_threads(shares) schedule(static, 1) if (n >= kMinPointsForThreads)
  for (int t = 0; t < shares; ++t)
    for (Index i = share_begin(t); i < share_begin(t + 1); ++i)
      ++next[t][bucket_of[i]];
  // Offsets: bucket-major, then thread order within a bucket.
  std::vector<Index> starts(bucket_count + 1, 0);
  Index offset = 0;
  for (Index b = 0; b <= bucket_count; ++b) {
    starts[b] = offset;
    for (int t = 0; t < shares; ++t)
      offset += std::exchange(next[t][b], offset);
  }
  out.resize(static_cast<std::size_t>(starts[bucket_count]));
#pragma omp parallel for num_threads(shares) schedule(static, 1) if (n >= kMinPointsForThreads)
  for (int t = 0; t < shares; ++t)
    for (Index i = share_begin(t); i < share_begin(t + 1); ++i) {
      const std::int32_t b = bucket_of[i];
      if (b < bucket_count) out[next[t][b]++] = item(i);
    }
  return starts;
}

// A double's bits as an unsigned key whose ascending order is the doubles' descending order
// (-0.0 is first made +0.0, so that equal heights always have equal keys).
std::uint64_t descending_key(Real height) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(height + 0.0);
  constexpr std::uint64_t kSign = std::uint64_t{1} << 63;
  const std::uint64_t ascending = (bits & kSign) ? ~bits : bits | kSign;
  return ~ascending;
}

Real height_of_key(std::uint64_t key) {
  constexpr std::uint64_t kSign = std::uint64_t{1} << 63;
  const std::uint64_t ascending = ~key;
  return std::bit_cast<Real>((ascending & kSign) ? ascending & ~kSign : ~ascending);
}

struct KeyedPoint {
  std::uint64_t key;
  std::int32_t index;
};

// Stable LSD radix sort of one bucket by key, 11 bits a pass, only over the bits in which its keys differ
// (a bucket holds a narrow range of heights, so most of their high bits agree). `scratch` is as long.
void radix_sort(KeyedPoint* points, KeyedPoint* scratch, Index count) {
  if (count < 2) return;
  std::uint64_t low = points[0].key, high = points[0].key;
  for (Index i = 1; i < count; ++i) {
    low = std::min(low, points[i].key);
    high = std::max(high, points[i].key);
  }
  constexpr int kBits = 11;
  constexpr std::size_t kRadix = std::size_t{1} << kBits;
  const int width = std::bit_width(high - low);
  KeyedPoint* from = points;
  KeyedPoint* to = scratch;
  for (int shift = 0; shift < width; shift += kBits) {
    std::array<Index, kRadix + 1> starts{};
    for (Index i = 0; i < count; ++i)
      ++starts[((from[i].key - low) >> shift) % kRadix + 1];
    for (std::size_t d = 1; d <= kRadix; ++d)
      starts[d] += starts[d - 1];
    for (Index i = 0; i < count; ++i)
      to[starts[((from[i].key - low) >> shift) % kRadix]++] = from[i];
    std::swap(from, to);
  }
  if (from != points) std::copy(from, from + count, points);
}

// Exact levels: every distinct height, as the points sorted by descending height (ties in index order).
// Two stages, both cache-friendly: a stable counting sort into 2048 buckets by a monotone map of the height
// (few enough write streams to stay in cache), then a radix sort of each bucket's keys, buckets in parallel.
std::vector<KeyedPoint> sort_descending(const HeightMap& heights, int threads) {
  const Index n = heights.size();
  const Real* h = heights.data();
  const Real top = heights.maxCoeff(), bottom = heights.minCoeff();
  const Index bucket_count = std::clamp<Index>(n / 256, 1, 2048);
  // (top - h) * scale is monotone in h, so buckets never reorder heights.
  const Real scale = top > bottom ? static_cast<Real>(bucket_count) / (top - bottom) : 0.0;
  std::vector<std::int32_t> bucket_of(static_cast<std::size_t>(n));
#pragma omp parallel for num_threads(std::max(1, threads)) schedule(static) if (n >= kMinPointsForThreads)
  for (Index i = 0; i < n; ++i)
    bucket_of[i] =
        static_cast<std::int32_t>(std::min<Real>((top - h[i]) * scale, static_cast<Real>(bucket_count - 1)));
  std::vector<KeyedPoint> points;
  const std::vector<Index> starts = bucket_points(bucket_of, bucket_count, points, threads, [h](Index i) {
    return KeyedPoint{descending_key(h[i]), static_cast<std::int32_t>(i)};
  });
#pragma omp parallel num_threads(std::max(1, threads)) if (n >= kMinPointsForThreads)
  {
    std::vector<KeyedPoint> scratch;
#pragma omp for schedule(dynamic, 8)
    for (Index b = 0; b < bucket_count; ++b) {
      scratch.resize(static_cast<std::size_t>(starts[b + 1] - starts[b]));
      radix_sort(points.data() + starts[b], scratch.data(), starts[b + 1] - starts[b]);
    }
  }
  return points;
}

// Fixed levels z[0] > ... > z[count]: a point joins at the first level strictly below its height. The
// stable counting sort by that level keeps the points of one level in memory order.
JoinSchedule fixed_schedule(const HeightMap& heights, std::vector<Real> z, int threads) {
  const Index n = heights.size(), levels = static_cast<Index>(z.size());
  const Real* h = heights.data();
  const Real top = z.front(), step = (z.front() - z.back()) / static_cast<Real>(levels - 1);
  std::vector<std::int32_t> level_of(static_cast<std::size_t>(n));
#pragma omp parallel for num_threads(std::max(1, threads)) schedule(static) if (n >= kMinPointsForThreads)
  for (Index i = 0; i < n; ++i) {
    const Real height = h[i];
    Index k = levels;  // never joins: at or below the lowest level
    if (height > z.back()) {
      // A guess from the spacing, corrected against the stored levels so that h > z[k] holds exactly as
      // it is reported.
      k = step > 0 ? std::clamp<Index>(static_cast<Index>((top - height) / step) + 1, 0, levels - 1) : 0;
      while (k > 0 && height > z[k - 1])
        --k;
      while (!(height > z[k]))
        ++k;
    }
    level_of[i] = static_cast<std::int32_t>(k);
  }
  JoinSchedule schedule;
  const std::vector<Index> starts = bucket_points(level_of, levels, schedule.order, threads,
                                                  [](Index i) { return static_cast<std::int32_t>(i); });
  schedule.z = std::move(z);
  // {h > z[j]}: the points joining at levels 0..j.
  schedule.joined.assign(starts.begin() + 1, starts.end());
  return schedule;
}

std::vector<Real> fixed_levels(const HeightMap& heights, const SweepLevels& levels) {
  if (levels.count < 1)
    throw Error("sweep: the number of levels must be at least 1, got " + std::to_string(levels.count));
  const Real top = heights.maxCoeff();
  const Real bottom = levels.kind == SweepLevels::Kind::paper ? 0.0 : heights.minCoeff();
  if (levels.kind == SweepLevels::Kind::paper && !(top > 0))
    throw Error(
        "sweep: the paper's levels run from the highest height down to the mean plane z = 0, but the "
        "highest height is not above 0 (centre the surface first)");
  std::vector<Real> z(static_cast<std::size_t>(levels.count) + 1);
  const Real step = (top - bottom) / static_cast<Real>(levels.count);
  for (Index k = 0; k <= levels.count; ++k)
    z[k] = top - static_cast<Real>(k) * step;
  z.back() = bottom;
  return z;
}

// Union-find over grid points in one array (one cache miss per look-up): kAbsent for a point not yet
// added, -size for a root, the parent's index otherwise. Union by size, path halving.
class PointForest {
 public:
  static constexpr std::int32_t kAbsent = std::numeric_limits<std::int32_t>::max();
  explicit PointForest(Index n) : parent_(static_cast<std::size_t>(n)) {
    std::fill(parent_.data(), parent_.data() + n, kAbsent);
  }

  bool present(std::int32_t i) const { return parent_[i] != kAbsent; }
  const std::int32_t* data() const { return parent_.data(); }
  void add(std::int32_t i) { parent_[i] = -1; }
  std::int32_t find(std::int32_t i) {
    while (parent_[i] >= 0) {
      const std::int32_t up = parent_[i];
      if (parent_[up] >= 0) parent_[i] = parent_[up];
      i = up;
    }
    return i;
  }
  // Joins the component of `root` (a root) with that of j; returns the root of the union, and whether the
  // two were different components.
  std::int32_t unite(std::int32_t root, std::int32_t j, bool& merged) {
    const std::int32_t other = find(j);
    merged = other != root;
    if (!merged) return root;
    // Sizes are stored negated: the larger component has the more negative value.
    const bool root_larger = parent_[root] <= parent_[other];
    const std::int32_t winner = root_larger ? root : other, loser = root_larger ? other : root;
    parent_[winner] += parent_[loser];
    parent_[loser] = winner;
    return winner;
  }

 private:
  LargeBuffer<std::int32_t> parent_;
};

// Neighbour offsets and wrap rules of a topology. Interior points use fixed index offsets; points on the
// border go through the general rule with wrap-around.
class Neighbourhood {
 public:
  Neighbourhood(Index nx, Index ny, const Topology& t) : nx_(nx), ny_(ny), topology_(t) {
    const bool eight = t.connectivity == Connectivity::eight;
    for (Index dy = -1; dy <= 1; ++dy)
      for (Index dx = -1; dx <= 1; ++dx)
        if ((dx != 0 || dy != 0) && (eight || dx == 0 || dy == 0)) steps_.push_back({dx, dy});
  }

  template <typename Visit>
  void for_each(std::int32_t i, Visit&& visit) const {
    const Index x = i % nx_, y = i / nx_;
    if (x > 0 && x + 1 < nx_ && y > 0 && y + 1 < ny_) {
      for (const auto& [dx, dy] : steps_)
        visit(static_cast<std::int32_t>(i + dy * nx_ + dx));
      return;
    }
    // On tiny periodic grids a neighbour may coincide with another or with the point itself; uniting
    // twice or with itself changes nothing.
    for (const auto& [dx, dy] : steps_) {
      Index xn = x + dx, yn = y + dy;
      if (xn < 0 || xn >= nx_) {
        if (!topology_.wrap_x) continue;
        xn = (xn + nx_) % nx_;
      }
      if (yn < 0 || yn >= ny_) {
        if (!topology_.wrap_y) continue;
        yn = (yn + ny_) % ny_;
      }
      visit(static_cast<std::int32_t>(yn * nx_ + xn));
    }
  }

 private:
  Index nx_, ny_;
  Topology topology_;
  std::vector<std::pair<Index, Index>> steps_;
};

// Grows a union-find forest point by point and counts its components.
class ComponentCounter {
 public:
  ComponentCounter(Index nx, Index ny, const Topology& topology)
      : n_(nx * ny), nx_(nx), forest_(nx * ny), neighbourhood_(nx, ny, topology) {}

  // Points come in height order, scattered over the grid: fetching the neighbourhood of a point a few
  // places ahead lets its cache misses overlap with the work on the current one.
  void prefetch(std::int32_t i) const {
    const std::int32_t* parent = forest_.data();
    __builtin_prefetch(parent + i);
    if (i >= nx_) __builtin_prefetch(parent + i - nx_);
    if (i + nx_ < n_) __builtin_prefetch(parent + i + nx_);
  }

  void add(std::int32_t i) {
    forest_.add(i);
    ++components_;
    std::int32_t root = i;
    neighbourhood_.for_each(i, [&](std::int32_t j) {
      if (!forest_.present(j)) return;
      bool merged = false;
      root = forest_.unite(root, j, merged);
      if (merged) --components_;
    });
  }

  Index components() const { return components_; }

 private:
  Index n_, nx_;
  PointForest forest_;
  Neighbourhood neighbourhood_;
  Index components_ = 0;
};

constexpr Index kPrefetchDistance = 12;

// The exact sweep: a level at every distinct height, recorded just before the points at that height join.
void exact_sweep(const HeightMap& heights, ComponentCounter& counter, SweepCurve& curve, int threads) {
  const std::vector<KeyedPoint> points = sort_descending(heights, threads);
  const Index n = static_cast<Index>(points.size());
  for (Index k = 0; k < n; ++k) {
    if (k + kPrefetchDistance < n) counter.prefetch(points[k + kPrefetchDistance].index);
    if (k == 0 || points[k].key != points[k - 1].key) {
      curve.z.push_back(height_of_key(points[k].key));
      curve.points.push_back(k);
      curve.spots.push_back(counter.components());
    }
    counter.add(points[k].index);
  }
}

// The sweep at fixed levels: the points of one level join in memory order, then the level is recorded.
void fixed_sweep(const HeightMap& heights, const SweepLevels& levels, ComponentCounter& counter,
                 SweepCurve& curve, int threads) {
  const JoinSchedule schedule = fixed_schedule(heights, fixed_levels(heights, levels), threads);
  const Index total = static_cast<Index>(schedule.order.size());
  Index added = 0;
  for (std::size_t level = 0; level < schedule.z.size(); ++level) {
    for (; added < schedule.joined[level]; ++added) {
      if (added + kPrefetchDistance < total) counter.prefetch(schedule.order[added + kPrefetchDistance]);
      counter.add(schedule.order[added]);
    }
    curve.z.push_back(schedule.z[level]);
    curve.points.push_back(added);
    curve.spots.push_back(counter.components());
  }
}

}  // namespace

SweepCurve sweep(const Surface& surface, const SweepLevels& levels, const Topology& topology, int threads) {
  const Index n = surface.heights().size();
  if (n >= std::numeric_limits<std::int32_t>::max())
    throw Error("sweep: more points than 32-bit indices hold");
  SweepCurve curve;
  curve.topology = topology;
  curve.levels = levels;
  curve.nominal_area = surface.grid().nominal_area();
  // The union-find pass is sequential: each point's effect depends on every point added before it.
  ComponentCounter counter(surface.nx(), surface.ny(), topology);
  if (levels.kind == SweepLevels::Kind::exact)
    exact_sweep(surface.heights(), counter, curve, threads);
  else
    fixed_sweep(surface.heights(), levels, counter, curve, threads);
  curve.area_fraction.resize(curve.points.size());
  for (std::size_t j = 0; j < curve.points.size(); ++j)
    curve.area_fraction[j] = static_cast<Real>(curve.points[j]) / static_cast<Real>(n);
  return curve;
}

}  // namespace contactbench
