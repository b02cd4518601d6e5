// Connected-component labelling (core/labelling.hpp, docs/theory.md section 3): against a breadth-first flood
// fill on random maps for every topology and thread count, then hard cases with counts reasoned by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>

#include <array>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "contactbench/core/labelling.hpp"
#include "contactbench/core/topology.hpp"
#include "reference_labelling.hpp"

namespace contactbench {
namespace {

using reference::reference_labelling;
using reference::ReferenceLabelling;

// Every combination of connectivity x wrap_x x wrap_y.
std::vector<Topology> all_topologies() {
  std::vector<Topology> result;
  for (const Connectivity c : {Connectivity::four, Connectivity::eight})
    for (const bool wx : {false, true})
      for (const bool wy : {false, true})
        result.push_back({c, wx, wy});
  return result;
}

std::string name(const BinaryMap& map, const Topology& t, int threads) {
  std::ostringstream out;
  out << map.cols() << " x " << map.rows() << " (nx x ny), " << describe(t) << ", threads " << threads;
  return out.str();
}

BinaryMap random_map(Index ny, Index nx, double density, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  BinaryMap map(ny, nx);
  for (Index iy = 0; iy < ny; ++iy)
    for (Index ix = 0; ix < nx; ++ix)
      map(iy, ix) = u(rng) < density ? 1 : 0;
  return map;
}

// Checks `got` against the flood fill: the count, the partition, labels in 1..count and 0 exactly on the
// background, the areas, and the raster-order numbering the header promises (which makes the labels equal
// to the flood fill's ids + 1, since the flood fill starts its components in raster order).
void expect_matches_reference(const BinaryMap& map, const Topology& t, int threads, const Labelling& got,
                              const ReferenceLabelling& want) {
  const std::string what = name(map, t, threads);
  const Index ny = map.rows(), nx = map.cols();
  ASSERT_EQ(got.labels.rows(), ny) << what;
  ASSERT_EQ(got.labels.cols(), nx) << what;
  ASSERT_EQ(got.count, want.count) << what;
  ASSERT_EQ(static_cast<Index>(got.areas.size()), got.count) << what;

  // Labels in range, 0 exactly on the background, and areas per label.
  std::vector<Index> area(static_cast<std::size_t>(got.count), 0);
  for (Index iy = 0; iy < ny; ++iy)
    for (Index ix = 0; ix < nx; ++ix) {
      const std::int32_t label = got.labels(iy, ix);
      if (map(iy, ix) == 0) {
        ASSERT_EQ(label, 0) << what << " background at (ix, iy) = (" << ix << ", " << iy << ")";
      } else {
        ASSERT_GE(label, 1) << what << " at (ix, iy) = (" << ix << ", " << iy << ")";
        ASSERT_LE(label, got.count) << what << " at (ix, iy) = (" << ix << ", " << iy << ")";
        ++area[static_cast<std::size_t>(label - 1)];
      }
    }
  for (Index k = 0; k < got.count; ++k)
    ASSERT_EQ(got.areas[static_cast<std::size_t>(k)], area[static_cast<std::size_t>(k)])
        << what << " area of label " << k + 1;

  // The partition: two points share a label iff they share a reference id. Mapping label -> id and
  // id -> label must both be functions (a bijection between the two numberings).
  std::vector<Index> id_of_label(static_cast<std::size_t>(got.count) + 1, -1);
  std::vector<Index> label_of_id(static_cast<std::size_t>(want.count), -1);
  for (Index p = 0; p < ny * nx; ++p) {
    const Index id = want.id[static_cast<std::size_t>(p)];
    if (id < 0) continue;
    const Index label = got.labels(p / nx, p % nx);
    Index& a = id_of_label[static_cast<std::size_t>(label)];
    Index& b = label_of_id[static_cast<std::size_t>(id)];
    if (a < 0) a = id;
    if (b < 0) b = label;
    ASSERT_EQ(a, id) << what << ": label " << label << " spans two components, at point " << p;
    ASSERT_EQ(b, label) << what << ": a component carries two labels, at point " << p;
  }

  // Numbering (labelling.hpp), whatever the thread count: raster order of each component's first point for
  // 4-connectivity, which is the flood fill's id order; raster order of its first 2 x 2 block for
  // 8-connectivity (a block never holds two components, so the order is strict).
  std::vector<Index> order_key(static_cast<std::size_t>(want.count), std::numeric_limits<Index>::max());
  for (Index p = 0; p < ny * nx; ++p) {
    const Index id = want.id[static_cast<std::size_t>(p)];
    if (id < 0) continue;
    const Index y = p / nx, x = p % nx;
    const Index key = t.connectivity == Connectivity::four ? p : (y / 2) * ((nx + 1) / 2) + x / 2;
    order_key[static_cast<std::size_t>(id)] = std::min(order_key[static_cast<std::size_t>(id)], key);
  }
  std::vector<Index> by_key(static_cast<std::size_t>(want.count));
  std::iota(by_key.begin(), by_key.end(), 0);
  std::sort(by_key.begin(), by_key.end(), [&](Index a, Index b) { return order_key[a] < order_key[b]; });
  std::vector<Index> expected_label(static_cast<std::size_t>(want.count));
  for (Index rank = 0; rank < want.count; ++rank)
    expected_label[by_key[rank]] = rank + 1;
  for (Index p = 0; p < ny * nx; ++p) {
    const Index id = want.id[static_cast<std::size_t>(p)];
    if (id < 0) continue;
    ASSERT_EQ(got.labels(p / nx, p % nx), expected_label[static_cast<std::size_t>(id)])
        << what << ": labels are not numbered in the documented raster order (point " << p << ")";
  }
}

// Label with 1, 2 and 3 threads: each must match the reference, and all three must be identical.
void check_all_threads(const BinaryMap& map, const Topology& t) {
  const ReferenceLabelling want = reference_labelling(map, t);
  const Labelling one = label_components(map, t, 1);
  expect_matches_reference(map, t, 1, one, want);
  for (const int threads : {2, 3}) {
    const Labelling many = label_components(map, t, threads);
    expect_matches_reference(map, t, threads, many, want);
    ASSERT_EQ(many.count, one.count) << name(map, t, threads);
    ASSERT_TRUE((many.labels == one.labels).all()) << name(map, t, threads) << " differs from 1 thread";
    ASSERT_EQ(many.areas, one.areas) << name(map, t, threads);
  }
}

Index count(const BinaryMap& map, const Topology& t, int threads = 1) {
  return label_components(map, t, threads).count;
}

TEST(Labelling, MatchesFloodFillOnRandomMaps) {
  // nx x ny: single points, single rows and columns, 2-wide grids (where a wrapped neighbour is the same
  // point twice), odd sizes, and sizes larger than a stripe of 2 or 3 threads.
  const std::vector<std::array<Index, 2>> sizes = {{1, 1},   {1, 7},   {7, 1},   {1, 40}, {40, 1},
                                                   {2, 2},   {2, 9},   {9, 2},   {3, 5},  {5, 3},
                                                   {17, 13}, {64, 64}, {100, 37}};
  const std::vector<double> densities = {0.1, 0.3, 0.5, 0.6, 0.9};
  const std::vector<Topology> topologies = all_topologies();
  std::uint64_t seed = 0;
  std::size_t rotation = 0;
  for (const auto& [nx, ny] : sizes) {
    const int seeds = nx * ny <= 64 ? 8 : 4;  // more draws where maps are small and cheap
    for (const double density : densities)
      for (int s = 0; s < seeds; ++s) {
        const BinaryMap map = random_map(ny, nx, density, 0x5eed0000ULL + seed++);
        // One thread against the reference for every topology (cheap) ...
        for (const Topology& t : topologies) {
          expect_matches_reference(map, t, 1, label_components(map, t, 1), reference_labelling(map, t));
          if (HasFatalFailure()) return;
        }
        // ... and 2 and 3 threads for one topology per map, taken in turn, so that every size and density
        // sees several topologies and every topology sees every size. (Each multi-threaded call starts a
        // thread team: on a loaded 2-core machine that costs milliseconds, so their number is kept modest.)
        check_all_threads(map, topologies[rotation++ % topologies.size()]);
        if (HasFatalFailure()) return;
      }
  }
}

TEST(Labelling, MatchesFloodFillOnALargeMap) {
  // 320 x 256 = 81920 points: large enough that an implementation which keeps small maps on one thread
  // (opening a thread team costs more than labelling a few thousand points) really runs its stripes in
  // parallel. Densities around the percolation thresholds (0.59 for 4-, 0.41 for 8-connectivity) give
  // components spanning many stripes.
  std::uint64_t seed = 0xb16ULL;
  for (const double density : {0.4, 0.6})
    for (const Topology t :
         {Topology{Connectivity::four, true, true}, Topology{Connectivity::eight, true, true},
          Topology{Connectivity::four, false, false}, Topology{Connectivity::eight, true, false}}) {
      const BinaryMap map = random_map(256, 320, density, seed++);
      check_all_threads(map, t);
      if (HasFatalFailure()) return;
    }
}

TEST(Labelling, AllBackgroundHasNoComponent) {
  for (const Topology& t : all_topologies())
    for (const int threads : {1, 2, 3}) {
      const BinaryMap map = BinaryMap::Zero(11, 6);
      const Labelling got = label_components(map, t, threads);
      EXPECT_EQ(got.count, 0) << describe(t);
      EXPECT_TRUE(got.areas.empty()) << describe(t);
      EXPECT_TRUE((got.labels == 0).all()) << describe(t);
    }
}

TEST(Labelling, AllForegroundIsOneComponent) {
  for (const Topology& t : all_topologies())
    for (const int threads : {1, 2, 3})
      for (const auto& [ny, nx] :
           std::vector<std::array<Index, 2>>{{1, 1}, {1, 5}, {5, 1}, {2, 2}, {12, 7}}) {
        const BinaryMap map = BinaryMap::Ones(ny, nx);
        const Labelling got = label_components(map, t, threads);
        EXPECT_EQ(got.count, 1) << nx << " x " << ny << ", " << describe(t);
        ASSERT_EQ(got.areas.size(), 1u);
        EXPECT_EQ(got.areas[0], nx * ny);
        EXPECT_TRUE((got.labels == 1).all());
      }
}

TEST(Labelling, Checkerboard) {
  // Foreground where ix + iy is even, on an 8 x 6 grid (both sides even): 24 foreground points.
  // 4-connectivity: the four neighbours of a foreground point all have odd ix + iy, also across a periodic
  // seam because the sides are even (column 0 meets column 7: parities differ). So every point is alone: 24.
  // 8-connectivity: the diagonal neighbours (ix +- 1, iy +- 1) keep the parity, and the even sublattice is
  // connected by diagonal steps when both sides are >= 2 ((0,0) -> (1,1) -> (2,0) ...): one component.
  BinaryMap map(6, 8);
  for (Index iy = 0; iy < 6; ++iy)
    for (Index ix = 0; ix < 8; ++ix)
      map(iy, ix) = (ix + iy) % 2 == 0 ? 1 : 0;
  for (const Topology& t : all_topologies())
    for (const int threads : {1, 2, 3}) {
      EXPECT_EQ(count(map, t, threads), t.connectivity == Connectivity::four ? 24 : 1) << describe(t);
      check_all_threads(map, t);
    }

  // On a 7 x 6 grid (odd nx) with wrap_x and 4-connectivity, column 0 and column 6 have equal parity:
  // the foreground points (0, iy) and (6, iy) for even iy touch across the seam. 21 foreground points
  // (rows 0, 2, 4 have 4 each, rows 1, 3, 5 have 3 each); each of the 3 even rows joins one pair: 18.
  BinaryMap odd(6, 7);
  for (Index iy = 0; iy < 6; ++iy)
    for (Index ix = 0; ix < 7; ++ix)
      odd(iy, ix) = (ix + iy) % 2 == 0 ? 1 : 0;
  EXPECT_EQ(count(odd, {Connectivity::four, false, false}), 21);
  EXPECT_EQ(count(odd, {Connectivity::four, true, false}), 18);
  EXPECT_EQ(count(odd, {Connectivity::four, true, false}, 2), 18);
  // wrap_y with ny = 6 even: row 0 meets row 5, parities differ, nothing joins.
  EXPECT_EQ(count(odd, {Connectivity::four, false, true}), 21);
}

TEST(Labelling, DiagonalLine) {
  // (i, i) on an n x n grid: diagonal steps only, so n spots with 4-connectivity (also with wrap: a
  // 4-neighbour of (i, i) is never on the diagonal for n >= 2) and one spot with 8-connectivity.
  for (const Index n : {2, 5, 16}) {
    BinaryMap map = BinaryMap::Zero(n, n);
    for (Index i = 0; i < n; ++i)
      map(i, i) = 1;
    for (const Topology& t : all_topologies())
      for (const int threads : {1, 2, 3})
        EXPECT_EQ(count(map, t, threads), t.connectivity == Connectivity::four ? n : 1)
            << "n = " << n << ", " << describe(t);
  }
  // The anti-diagonal (n - 1 - i, i) too: the 8-neighbour scan must look up-right as well as up-left.
  BinaryMap anti = BinaryMap::Zero(9, 9);
  for (Index i = 0; i < 9; ++i)
    anti(i, 8 - i) = 1;
  for (const Topology& t : all_topologies())
    EXPECT_EQ(count(anti, t), t.connectivity == Connectivity::four ? 9 : 1) << describe(t);
}

TEST(Labelling, SpotJoinedAcrossThePeriodicEdgeInX) {
  // A 2 x 2 block cut by the seam at x: columns 0 and 9 of a 10 x 6 grid, rows 2 and 3.
  BinaryMap map = BinaryMap::Zero(6, 10);
  map(2, 0) = map(3, 0) = map(2, 9) = map(3, 9) = 1;
  for (const Connectivity c : {Connectivity::four, Connectivity::eight})
    for (const int threads : {1, 2, 3}) {
      EXPECT_EQ(count(map, {c, false, false}, threads), 2);
      EXPECT_EQ(count(map, {c, true, false}, threads), 1);
      EXPECT_EQ(count(map, {c, false, true}, threads), 2);
      EXPECT_EQ(count(map, {c, true, true}, threads), 1);
    }
}

TEST(Labelling, SpotJoinedAcrossThePeriodicEdgeInY) {
  // The same across the seam at y: rows 0 and 8 of a 7 x 9 grid, columns 3 and 4. With 2 or 3 threads the
  // first and last rows lie in different stripes, so the seam merge runs between stripes.
  BinaryMap map = BinaryMap::Zero(9, 7);
  map(0, 3) = map(0, 4) = map(8, 3) = map(8, 4) = 1;
  for (const Connectivity c : {Connectivity::four, Connectivity::eight})
    for (const int threads : {1, 2, 3}) {
      EXPECT_EQ(count(map, {c, false, false}, threads), 2);
      EXPECT_EQ(count(map, {c, true, false}, threads), 2);
      EXPECT_EQ(count(map, {c, false, true}, threads), 1);
      EXPECT_EQ(count(map, {c, true, true}, threads), 1);
    }
}

TEST(Labelling, SpotsJoinedOnlyAcrossTheCorner) {
  // Two points on opposite corners, (0, 0) and (nx-1, ny-1): they touch only diagonally through the corner
  // of the torus, which needs both wraps and 8-connectivity.
  BinaryMap diagonal = BinaryMap::Zero(5, 8);
  diagonal(0, 0) = diagonal(4, 7) = 1;
  // The four corner points: each wrap joins them in pairs, both wraps (any connectivity) join all four.
  BinaryMap corners = BinaryMap::Zero(5, 8);
  corners(0, 0) = corners(0, 7) = corners(4, 0) = corners(4, 7) = 1;
  for (const int threads : {1, 2, 3}) {
    for (const Connectivity c : {Connectivity::four, Connectivity::eight}) {
      const bool eight = c == Connectivity::eight;
      EXPECT_EQ(count(diagonal, {c, false, false}, threads), 2);
      EXPECT_EQ(count(diagonal, {c, true, false}, threads), 2);
      EXPECT_EQ(count(diagonal, {c, false, true}, threads), 2);
      EXPECT_EQ(count(diagonal, {c, true, true}, threads), eight ? 1 : 2);

      EXPECT_EQ(count(corners, {c, false, false}, threads), 4);
      EXPECT_EQ(count(corners, {c, true, false}, threads), 2);
      EXPECT_EQ(count(corners, {c, false, true}, threads), 2);
      EXPECT_EQ(count(corners, {c, true, true}, threads), 1);
    }
  }
  for (const Topology& t : all_topologies()) {
    check_all_threads(diagonal, t);
    check_all_threads(corners, t);
  }
}

TEST(Labelling, CombMergesLabelsMetLate) {
  // Teeth in the even columns of rows 0..ny-2, joined by the full last row: a raster scan gives each tooth
  // its own provisional label and only the last row merges them, all into one component numbered 1.
  BinaryMap comb = BinaryMap::Zero(12, 15);
  for (Index iy = 0; iy < 11; ++iy)
    for (Index ix = 0; ix < 15; ix += 2)
      comb(iy, ix) = 1;
  comb.row(11).setOnes();
  // The comb upside down (joined at the top) is easy for a raster scan; keep it as a control.
  const BinaryMap flipped = comb.colwise().reverse();
  // Without the joining row: 8 teeth (with wrap_x on nx = 15, columns 0 and 14 are both teeth and touch).
  BinaryMap teeth = comb;
  teeth.row(11).setZero();
  for (const Topology& t : all_topologies()) {
    for (const int threads : {1, 2, 3}) {
      EXPECT_EQ(count(comb, t, threads), 1) << describe(t);
      EXPECT_EQ(count(flipped, t, threads), 1) << describe(t);
      EXPECT_EQ(count(teeth, t, threads), t.wrap_x ? 7 : 8) << describe(t);
    }
    check_all_threads(comb, t);
    check_all_threads(teeth, t);
  }
}

TEST(Labelling, SpiralIsOneComponent) {
  // A square spiral on a 21 x 21 grid: a 1-wide path turning inwards (right 20, down 20, left 20, up 18,
  // right 18, down 16, ...), its turns 1 apart. A raster scan enters it dozens of times (every turn going
  // down creates a new provisional label), so it takes a chain of merges to find one path. The gaps keep
  // the turns apart for either connectivity; the path reaches every border, so the wraps change nothing.
  const Index n = 21;
  BinaryMap spiral = BinaryMap::Zero(n, n);
  const Index step_x[4] = {1, 0, -1, 0}, step_y[4] = {0, 1, 0, -1};
  Index x = 0, y = 0, length = n - 1;
  spiral(0, 0) = 1;
  for (int segment = 1; length > 0; ++segment) {
    const int direction = (segment - 1) % 4;
    for (Index s = 0; s < length; ++s) {
      x += step_x[direction];
      y += step_y[direction];
      spiral(y, x) = 1;
    }
    if (segment >= 3 && segment % 2 == 1) length -= 2;  // lengths n-1, n-1, n-1, n-3, n-3, n-5, ...
  }
  for (const Topology& t : all_topologies()) {
    for (const int threads : {1, 2, 3})
      EXPECT_EQ(count(spiral, t, threads), 1) << describe(t);
    check_all_threads(spiral, t);
  }
  // Cut the path once in the middle of the outer turn: two components, numbered in raster order.
  spiral(0, 10) = 0;
  EXPECT_EQ(count(spiral, {Connectivity::four, false, false}), 2);
  for (const Topology& t : all_topologies())
    check_all_threads(spiral, t);
}

TEST(Labelling, ShapesAcrossTheStripeBorder) {
  // Wherever the stripes of 2, 3 or 4 threads split the rows, a shape crossing that border must stay one
  // component. Try every row border r of a 10-row map rather than guess where the split falls.
  const Index ny = 10, nx = 9;
  for (Index r = 1; r < ny; ++r) {
    // A U: two bars in rows [0, r) joined by a bar in row r, so the top stripe may see two spots.
    BinaryMap u = BinaryMap::Zero(ny, nx);
    for (Index iy = 0; iy < r; ++iy)
      u(iy, 2) = u(iy, 6) = 1;
    for (Index ix = 2; ix <= 6; ++ix)
      u(r, ix) = 1;
    // An upside-down U: the bars below the border, joined in row r - 1.
    BinaryMap n = BinaryMap::Zero(ny, nx);
    for (Index iy = r; iy < ny; ++iy)
      n(iy, 2) = n(iy, 6) = 1;
    for (Index ix = 2; ix <= 6; ++ix)
      n(r - 1, ix) = 1;
    // Two points touching diagonally across the border, both directions: 8-connectivity joins them.
    BinaryMap diag = BinaryMap::Zero(ny, nx);
    diag(r - 1, 3) = diag(r, 4) = 1;
    BinaryMap anti = BinaryMap::Zero(ny, nx);
    anti(r - 1, 5) = anti(r, 4) = 1;
    for (const int threads : {2, 3, 4})
      for (const Connectivity c : {Connectivity::four, Connectivity::eight}) {
        const Topology t{c, false, false};
        EXPECT_EQ(count(u, t, threads), 1) << "border " << r << ", threads " << threads;
        EXPECT_EQ(count(n, t, threads), 1) << "border " << r << ", threads " << threads;
        const Index expected = c == Connectivity::eight ? 1 : 2;
        EXPECT_EQ(count(diag, t, threads), expected) << "border " << r << ", threads " << threads;
        EXPECT_EQ(count(anti, t, threads), expected) << "border " << r << ", threads " << threads;
      }
    for (const Topology& t :
         {Topology{Connectivity::four, true, true}, Topology{Connectivity::eight, true, true}}) {
      check_all_threads(u, t);
      check_all_threads(n, t);
      check_all_threads(diag, t);
    }
  }
}

TEST(Labelling, MoreThreadsThanRows) {
  // A single row, two rows: stripes would be empty; the result must not change.
  const BinaryMap row = random_map(1, 50, 0.6, 77);
  const BinaryMap two = random_map(2, 30, 0.5, 78);
  for (const Topology& t : all_topologies())
    for (const int threads : {4, 8}) {
      const ReferenceLabelling want_row = reference_labelling(row, t);
      expect_matches_reference(row, t, threads, label_components(row, t, threads), want_row);
      const ReferenceLabelling want_two = reference_labelling(two, t);
      expect_matches_reference(two, t, threads, label_components(two, t, threads), want_two);
    }
}

TEST(Threshold, IsStrictlyAbove) {
  HeightMap h(2, 3);
  h << 1.0, 2.0, 2.0, std::nextafter(2.0, 3.0), std::nextafter(2.0, 1.0), -5.0;
  const BinaryMap above = threshold_above(h, 2.0);
  ASSERT_EQ(above.rows(), 2);
  ASSERT_EQ(above.cols(), 3);
  EXPECT_EQ(above(0, 0), 0);
  EXPECT_EQ(above(0, 1), 0);  // h == z is not above
  EXPECT_EQ(above(0, 2), 0);
  EXPECT_EQ(above(1, 0), 1);  // one ulp above
  EXPECT_EQ(above(1, 1), 0);  // one ulp below
  EXPECT_EQ(above(1, 2), 0);
  // Everything is above a level below the minimum; nothing is above the maximum.
  EXPECT_TRUE((threshold_above(h, -6.0) == 1).all());
  EXPECT_TRUE((threshold_above(h, h.maxCoeff()) == 0).all());
  // Only the values 0 and 1 appear, and the map agrees with the obvious loop.
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> level(0, 4);
  HeightMap q(13, 8);
  for (Index iy = 0; iy < q.rows(); ++iy)
    for (Index ix = 0; ix < q.cols(); ++ix)
      q(iy, ix) = 0.25 * level(rng);
  for (const Real z : {-1.0, 0.0, 0.25, 0.5, 0.6, 0.75, 1.0, 2.0})
    EXPECT_TRUE((threshold_above(q, z) == reference::reference_threshold(q, z)).all()) << "z = " << z;
}

TEST(Labelling, AnyNonZeroValueIsForeground) {
  // Maps from image tools hold 255 for foreground: the labeller must treat every non-zero value alike.
  for (const Connectivity c : {Connectivity::four, Connectivity::eight}) {
    BinaryMap ones(6, 7), bytes(6, 7);
    std::mt19937_64 random(11);
    for (Index i = 0; i < ones.size(); ++i) {
      ones.data()[i] = random() % 2;
      bytes.data()[i] = ones.data()[i] ? 255 : 0;
    }
    const Topology t{c, false, false};
    const Labelling a = label_components(ones, t, 2), b = label_components(bytes, t, 2);
    EXPECT_EQ(a.count, b.count);
    EXPECT_TRUE((a.labels == b.labels).all());
    EXPECT_EQ(a.areas, b.areas);
  }
}

TEST(Labelling, RowsTouchingAtOnePointUnderLongRuns) {
  // Two full rows (0 and 3) with one point each between them, in rows 1 and 2 at columns a and b: rows 0-1
  // and 2-3 are two spots, joined only if the two points touch, |a - b| <= 1 for 8-connectivity, a == b
  // for 4-connectivity (with wrap_x, also across the seam). Every column of rows 0-1 and of rows 2-3 is
  // foreground, so a scan that pairs rows sees two bands overlapping from end to end, touching at one
  // place; widths around 64 and 128 put that place on either side of a word boundary or deep inside a
  // long overlap. Rows 4 and 5 stay empty, so wrap_y joins nothing.
  for (const Index nx : {63, 64, 65, 129, 200}) {
    std::vector<Index> columns = {0, 1, 62, 63, 64, 65, 100, 127, 128, nx - 2, nx - 1};
    std::erase_if(columns, [&](Index x) { return x < 0 || x >= nx; });
    for (const Index a : columns)
      for (const Index shift : {-2, -1, 0, 1, 2}) {
        const Index b = a + shift;
        if (b < 0 || b >= nx) continue;
        BinaryMap map = BinaryMap::Zero(6, nx);
        map.row(0).setOnes();
        map.row(3).setOnes();
        map(1, a) = map(2, b) = 1;
        for (const int threads : {1, 2}) {
          EXPECT_EQ(count(map, {Connectivity::eight, false, false}, threads), shift * shift <= 1 ? 1 : 2)
              << "nx " << nx << ", a " << a << ", b " << b << ", threads " << threads;
          EXPECT_EQ(count(map, {Connectivity::four, false, false}, threads), shift == 0 ? 1 : 2)
              << "nx " << nx << ", a " << a << ", b " << b << ", threads " << threads;
        }
        for (const Topology& t : all_topologies()) {
          expect_matches_reference(map, t, 1, label_components(map, t, 1), reference_labelling(map, t));
          if (HasFatalFailure()) return;
        }
      }
  }
}

TEST(Labelling, AnyNonZeroValueIsForegroundOnWideMaps) {
  // The same as above on rows wide enough for a labeller to read many points at once (64 and more), with
  // every kind of non-zero byte (the high bit set or not).
  const std::uint8_t values[] = {1, 2, 127, 128, 255};
  for (const Index nx : {64, 150, 257}) {
    const BinaryMap ones = random_map(9, nx, 0.55, 0xb17e5ULL + static_cast<std::uint64_t>(nx));
    BinaryMap bytes(ones.rows(), ones.cols());
    for (Index i = 0; i < ones.size(); ++i)
      bytes.data()[i] = ones.data()[i] ? values[i % 5] : 0;
    for (const Topology& t : all_topologies())
      for (const int threads : {1, 2}) {
        const Labelling a = label_components(ones, t, threads), b = label_components(bytes, t, threads);
        EXPECT_EQ(a.count, b.count) << describe(t);
        EXPECT_TRUE((a.labels == b.labels).all()) << describe(t);
        EXPECT_EQ(a.areas, b.areas) << describe(t);
        expect_matches_reference(bytes, t, threads, b, reference_labelling(bytes, t));
        if (HasFatalFailure()) return;
      }
  }
}

}  // namespace
}  // namespace contactbench
