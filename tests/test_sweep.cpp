// The geometric sweep (core/sweep.hpp, docs/theory.md section 3): A_c(z) and N(z) of {h > z} at every
// reported level against thresholding and flood-filling that level from scratch; level placement; hard cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "contactbench/core/generation.hpp"
#include "contactbench/core/sweep.hpp"
#include "reference_labelling.hpp"
#include "test_constants.hpp"

namespace contactbench {
namespace {

using reference::reference_sweep_at;
using reference::ReferenceLevel;

using testing::um;

// Connectivity 4/8 x (wrap both, wrap none, wrap only x).
std::vector<Topology> sweep_topologies() {
  std::vector<Topology> result;
  for (const Connectivity c : {Connectivity::four, Connectivity::eight}) {
    result.push_back({c, true, true});
    result.push_back({c, false, false});
    result.push_back({c, true, false});
  }
  return result;
}

Grid small_grid(Index nx, Index ny, bool periodic) {
  return {.nx = nx,
          .ny = ny,
          .lx = static_cast<Real>(nx) * um,
          .ly = static_cast<Real>(ny) * um,
          .periodic = periodic};
}

Surface random_surface(Index nx, Index ny, std::uint64_t seed) {
  const Grid grid = small_grid(nx, ny, true);
  const SelfAffinePsd psd{.sigma = 1 * um,
                          .hurst = 0.8,
                          .qr = 2 * std::min(grid.dqx(), grid.dqy()),
                          .qs = std::nullopt,
                          .anisotropy = 1};
  return generate_surface(grid, psd, seed);
}

// Independent uniform random heights: no spatial correlation, many small spots.
Surface white_surface(Index nx, Index ny, std::uint64_t seed, bool periodic = false) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  HeightMap h(ny, nx);
  for (Index iy = 0; iy < ny; ++iy)
    for (Index ix = 0; ix < nx; ++ix)
      h(iy, ix) = u(rng) * um;
  return Surface(small_grid(nx, ny, periodic), h);
}

Surface from_heights(const HeightMap& h, bool periodic = false) {
  return Surface(small_grid(h.cols(), h.rows(), periodic), h);
}

std::vector<Real> distinct_descending(const HeightMap& h) {
  std::vector<Real> v(h.data(), h.data() + h.size());
  std::sort(v.begin(), v.end(), [](Real a, Real b) { return a > b; });
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

std::string what(const Surface& s, const Topology& t, const char* levels, int threads) {
  std::ostringstream out;
  out << s.nx() << " x " << s.ny() << ", " << describe(t) << ", " << levels << " levels, threads " << threads;
  return out.str();
}

// Every row of the curve against thresholding and flood-filling its level from scratch; the bookkeeping
// (sizes, descending z, area fraction, topology, nominal area) too.
void expect_brute_force(const Surface& s, const SweepCurve& c, const Topology& t, const std::string& label) {
  const std::size_t n = c.z.size();
  ASSERT_GE(n, 1u) << label;
  ASSERT_EQ(c.area_fraction.size(), n) << label;
  ASSERT_EQ(c.points.size(), n) << label;
  ASSERT_EQ(c.spots.size(), n) << label;
  EXPECT_EQ(c.topology.connectivity, t.connectivity) << label;
  EXPECT_EQ(c.topology.wrap_x, t.wrap_x) << label;
  EXPECT_EQ(c.topology.wrap_y, t.wrap_y) << label;
  EXPECT_DOUBLE_EQ(c.nominal_area, s.grid().lx * s.grid().ly) << label;
  const Real total = static_cast<Real>(s.nx() * s.ny());
  for (std::size_t j = 0; j < n; ++j) {
    if (j > 0) {
      ASSERT_LT(c.z[j], c.z[j - 1]) << label << ": z not strictly descending at row " << j;
    }
    const ReferenceLevel want = reference_sweep_at(s.heights(), c.z[j], t);
    ASSERT_EQ(c.points[j], want.points) << label << ", row " << j << ", z = " << c.z[j];
    ASSERT_EQ(c.spots[j], want.components) << label << ", row " << j << ", z = " << c.z[j];
    // points / (nx ny), up to the round-off of however the division is written (a few ulp).
    ASSERT_DOUBLE_EQ(c.area_fraction[j], static_cast<Real>(c.points[j]) / total) << label << ", row " << j;
  }
}

// Brute force at selected rows only, for surfaces too large to flood-fill at every level.
void expect_brute_force_at(const Surface& s, const SweepCurve& c, const Topology& t, const std::string& label,
                           std::size_t rows) {
  const std::size_t n = c.z.size();
  ASSERT_GE(n, 2u) << label;
  const Real total = static_cast<Real>(s.nx() * s.ny());
  for (std::size_t k = 0; k < rows; ++k) {
    const std::size_t j = k * (n - 1) / (rows - 1);  // first and last rows included
    const ReferenceLevel want = reference_sweep_at(s.heights(), c.z[j], t);
    ASSERT_EQ(c.points[j], want.points) << label << ", row " << j << ", z = " << c.z[j];
    ASSERT_EQ(c.spots[j], want.components) << label << ", row " << j << ", z = " << c.z[j];
    ASSERT_DOUBLE_EQ(c.area_fraction[j], static_cast<Real>(c.points[j]) / total) << label << ", row " << j;
  }
}

void expect_identical(const SweepCurve& a, const SweepCurve& b, const std::string& label) {
  EXPECT_EQ(a.z, b.z) << label;
  EXPECT_EQ(a.area_fraction, b.area_fraction) << label;
  EXPECT_EQ(a.points, b.points) << label;
  EXPECT_EQ(a.spots, b.spots) << label;
  EXPECT_EQ(a.nominal_area, b.nominal_area) << label;
}

// The exact mode's levels: every distinct height, descending, from the maximum (nothing above) to the
// minimum (everything but the minimum's points above).
void expect_exact_levels(const Surface& s, const SweepCurve& c, const std::string& label) {
  const std::vector<Real> distinct = distinct_descending(s.heights());
  ASSERT_EQ(c.z.size(), distinct.size()) << label;
  EXPECT_EQ(c.z, distinct) << label;
  EXPECT_EQ(c.points.front(), 0) << label;
  EXPECT_EQ(c.spots.front(), 0) << label;
  const Index at_minimum = (s.heights() == s.heights().minCoeff()).count();
  EXPECT_EQ(c.points.back(), s.nx() * s.ny() - at_minimum) << label;
  EXPECT_EQ(c.levels.kind, SweepLevels::Kind::exact) << label;
}

TEST(Sweep, ExactLevelsMatchBruteForceOnRandomSurfaces) {
  struct Case {
    Index nx, ny;
    int seeds;
  };
  for (const Case& k : {Case{16, 16, 4}, Case{24, 10, 4}, Case{32, 32, 2}})
    for (int seed = 0; seed < k.seeds; ++seed) {
      const Surface periodic = random_surface(k.nx, k.ny, 1000 + static_cast<std::uint64_t>(seed));
      const Surface open = periodic.with_periodic(false);
      for (const Topology& t : sweep_topologies()) {
        const SweepCurve one = sweep(periodic, SweepLevels::exact(), t, 1);
        const std::string label = what(periodic, t, "exact", 1);
        expect_brute_force(periodic, one, t, label);
        expect_exact_levels(periodic, one, label);
        expect_identical(one, sweep(periodic, SweepLevels::exact(), t, 2), what(periodic, t, "exact", 2));
        // The topology argument decides the wrap, not the grid's flag: same heights, same answer.
        expect_identical(one, sweep(open, SweepLevels::exact(), t, 1), label + ", non-periodic grid");
        expect_identical(one, sweep(open, SweepLevels::exact(), t, 2), label + ", non-periodic grid");
        if (HasFatalFailure()) return;
      }
    }
}

TEST(Sweep, ExactLevelsMatchBruteForceOnWhiteNoise) {
  // Uncorrelated heights: many tiny spots that merge in every order, the union-find's hardest diet.
  for (int seed = 0; seed < 4; ++seed) {
    const Surface s = white_surface(20, 15, 2000 + static_cast<std::uint64_t>(seed));
    for (const Topology& t : sweep_topologies()) {
      const SweepCurve one = sweep(s, SweepLevels::exact(), t, 1);
      expect_brute_force(s, one, t, what(s, t, "exact", 1));
      expect_exact_levels(s, one, what(s, t, "exact", 1));
      expect_identical(one, sweep(s, SweepLevels::exact(), t, 2), what(s, t, "exact", 2));
      expect_identical(one, sweep(s, SweepLevels::exact(), t, 3), what(s, t, "exact", 3));
    }
  }
}

TEST(Sweep, UniformLevels) {
  for (const Index count : {1, 7, 40}) {
    const Surface s = random_surface(24, 16, 31 + static_cast<std::uint64_t>(count));
    const Real top = s.heights().maxCoeff(), bottom = s.heights().minCoeff();
    for (const Topology& t : sweep_topologies()) {
      const std::string label = what(s, t, "uniform", 1) + ", count " + std::to_string(count);
      const SweepCurve c = sweep(s, SweepLevels::uniform(count), t, 1);
      ASSERT_EQ(c.z.size(), static_cast<std::size_t>(count + 1)) << label;
      EXPECT_EQ(c.levels.kind, SweepLevels::Kind::uniform) << label;
      EXPECT_EQ(c.levels.count, count) << label;
      EXPECT_EQ(c.z.front(), top) << label;  // starts at the highest height: nothing above
      EXPECT_EQ(c.points.front(), 0) << label;
      EXPECT_EQ(c.spots.front(), 0) << label;
      // Equally spaced down to the minimum; 1e-12 of the range is far above the round-off of
      // top - j (top - bottom) / count (a few ulp of |h| ~ 1e-6 m) and far below a step.
      const Real step = (top - bottom) / static_cast<Real>(count);
      for (std::size_t j = 0; j < c.z.size(); ++j)
        EXPECT_NEAR(c.z[j], top - static_cast<Real>(j) * step, 1e-12 * (top - bottom))
            << label << ", row " << j;
      expect_brute_force(s, c, t, label);
      expect_identical(c, sweep(s, SweepLevels::uniform(count), t, 2), label + ", 2 threads");
    }
  }
}

TEST(Sweep, PaperLevels) {
  for (const Index count : {10, 500}) {
    const Surface s = random_surface(32, 16, 77 + static_cast<std::uint64_t>(count));  // zero mean
    const Real top = s.heights().maxCoeff();
    ASSERT_GT(top, 0);
    for (const Topology& t : sweep_topologies()) {
      const std::string label = what(s, t, "paper", 1) + ", count " + std::to_string(count);
      const SweepCurve c = sweep(s, SweepLevels::paper(count), t, 1);
      ASSERT_EQ(c.z.size(), static_cast<std::size_t>(count + 1)) << label;
      EXPECT_EQ(c.levels.kind, SweepLevels::Kind::paper) << label;
      EXPECT_EQ(c.z.front(), top) << label;
      EXPECT_EQ(c.points.front(), 0) << label;
      EXPECT_EQ(c.spots.front(), 0) << label;
      // Steps of h_max / count (count = 500: 0.002 h_max), down to the mean plane z = 0. The 1e-12
      // tolerances are round-off of h_max (1 - j / count) and the like, relative to h_max.
      const Real step = top / static_cast<Real>(count);
      EXPECT_NEAR(c.z[1] - c.z[0], -step, 1e-12 * step) << label;
      for (std::size_t j = 0; j < c.z.size(); ++j)
        EXPECT_NEAR(c.z[j], top - static_cast<Real>(j) * step, 1e-12 * top) << label << ", row " << j;
      EXPECT_NEAR(c.z.back(), 0.0, 1e-12 * top) << label;
      expect_brute_force(s, c, t, label);
      expect_identical(c, sweep(s, SweepLevels::paper(count), t, 2), label + ", 2 threads");
    }
  }
}

TEST(Sweep, LargeSurfaceWithThreads) {
  // 320 x 256 = 81920 points: large enough that an implementation which keeps small surfaces on one thread
  // really sorts and buckets in parallel. Flood-filling every one of ~82000 exact levels would take
  // minutes, so brute force checks 12 rows spread over each curve (first and last included); the exact
  // levels are checked in full against the distinct heights, and 2 threads against 1 row by row.
  const Grid grid = small_grid(320, 256, true);
  const SelfAffinePsd psd{
      .sigma = 1 * um, .hurst = 0.8, .qr = 4 * grid.dqx(), .qs = std::nullopt, .anisotropy = 1};
  const Surface s = generate_surface(grid, psd, 4242);
  // The same heights rounded to 0.25 um: a few dozen wide plateaus, every level checked.
  const Surface q = from_heights((s.heights() / (0.25 * um)).round() * (0.25 * um), true);
  for (const Topology t :
       {Topology{Connectivity::four, true, true}, Topology{Connectivity::eight, false, false},
        Topology{Connectivity::eight, true, false}}) {
    const SweepCurve exact = sweep(s, SweepLevels::exact(), t, 2);
    expect_exact_levels(s, exact, what(s, t, "exact", 2));
    expect_brute_force_at(s, exact, t, what(s, t, "exact", 2), 12);
    expect_identical(exact, sweep(s, SweepLevels::exact(), t, 1), what(s, t, "exact", 1));
    for (const SweepLevels levels : {SweepLevels::uniform(50), SweepLevels::paper(500)}) {
      const SweepCurve c = sweep(s, levels, t, 2);
      expect_brute_force_at(s, c, t, what(s, t, "fixed", 2), 12);
      expect_identical(c, sweep(s, levels, t, 1), what(s, t, "fixed", 1));
    }
    const SweepCurve plateaus = sweep(q, SweepLevels::exact(), t, 2);
    expect_exact_levels(q, plateaus, what(q, t, "exact", 2) + ", quantised");
    expect_brute_force(q, plateaus, t, what(q, t, "exact", 2) + ", quantised");
    expect_identical(plateaus, sweep(q, SweepLevels::exact(), t, 1), what(q, t, "exact", 1) + ", quantised");
    if (HasFatalFailure()) return;
  }
}

TEST(SweepHardCases, SignedZerosAreOneHeight) {
  // -0.0 == +0.0: one distinct height, one level, and neither zero is above the level 0. (An
  // implementation that sorts the bits of doubles must not see two heights there.)
  HeightMap h = HeightMap::Zero(4, 6);
  h(0, 0) = -0.0;
  h(1, 3) = -0.0;
  h(2, 2) = 1 * um;
  h(3, 5) = -1 * um;
  const Surface s = from_heights(h);
  for (const Topology& t : sweep_topologies()) {
    const SweepCurve c = sweep(s, SweepLevels::exact(), t, 2);
    expect_brute_force(s, c, t, what(s, t, "exact", 2));
    ASSERT_EQ(c.z.size(), 3u) << describe(t);
    EXPECT_EQ(c.z[1], 0.0);
    EXPECT_EQ(c.points, (std::vector<Index>{0, 1, 23}));
  }
}

TEST(SweepHardCases, ConstantSurfaceHasOneEmptyLevel) {
  const Surface s = from_heights(HeightMap::Constant(4, 5, 3 * um), true);
  for (const Topology& t : sweep_topologies())
    for (const int threads : {1, 2}) {
      const SweepCurve c = sweep(s, SweepLevels::exact(), t, threads);
      ASSERT_EQ(c.z.size(), 1u) << describe(t);
      EXPECT_EQ(c.z[0], 3 * um);
      EXPECT_EQ(c.points[0], 0);
      EXPECT_EQ(c.spots[0], 0);
      EXPECT_EQ(c.area_fraction[0], 0.0);
    }
}

TEST(SweepHardCases, SinglePixelPeak) {
  HeightMap h = HeightMap::Zero(5, 6);
  h(3, 2) = 1 * um;
  const Surface s = from_heights(h);
  for (const Topology& t : sweep_topologies())
    for (const int threads : {1, 2}) {
      const SweepCurve c = sweep(s, SweepLevels::exact(), t, threads);
      EXPECT_EQ(c.z, (std::vector<Real>{1 * um, 0.0})) << describe(t);
      EXPECT_EQ(c.points, (std::vector<Index>{0, 1})) << describe(t);
      EXPECT_EQ(c.spots, (std::vector<Index>{0, 1})) << describe(t);
      EXPECT_DOUBLE_EQ(c.area_fraction[1], 1.0 / 30.0);
    }
}

TEST(SweepHardCases, CheckerboardOfHeights) {
  // Peaks (1 um) where ix + iy is even on an 8 x 6 grid, 0 elsewhere. At z = 0 the 24 peaks stand alone
  // with 4-connectivity (even sides: also across the seams) and form one spot with 8-connectivity (the
  // diagonal steps connect the whole even sublattice).
  HeightMap h(6, 8);
  for (Index iy = 0; iy < 6; ++iy)
    for (Index ix = 0; ix < 8; ++ix)
      h(iy, ix) = (ix + iy) % 2 == 0 ? 1 * um : 0.0;
  const Surface s = from_heights(h, true);
  for (const Topology& t : sweep_topologies())
    for (const int threads : {1, 2}) {
      const SweepCurve c = sweep(s, SweepLevels::exact(), t, threads);
      ASSERT_EQ(c.z.size(), 2u);
      EXPECT_EQ(c.points[1], 24);
      EXPECT_EQ(c.spots[1], t.connectivity == Connectivity::four ? 24 : 1) << describe(t);
    }
  // Graded peaks (every peak a different height): the spots appear one by one; brute force at each level.
  HeightMap graded = h;
  for (Index iy = 0; iy < 6; ++iy)
    for (Index ix = 0; ix < 8; ++ix)
      if ((ix + iy) % 2 == 0) graded(iy, ix) = static_cast<Real>(1 + ix + 8 * iy) * um;
  const Surface g = from_heights(graded, true);
  for (const Topology& t : sweep_topologies()) {
    const SweepCurve c = sweep(g, SweepLevels::exact(), t, 2);
    expect_brute_force(g, c, t, what(g, t, "exact", 2));
    EXPECT_EQ(c.spots.back(), t.connectivity == Connectivity::four ? 24 : 1) << describe(t);
  }
}

TEST(SweepHardCases, SpotsJoinedOnlyAcrossThePeriodicEdge) {
  // On a 10 x 6 grid: (ix, iy) = (0, 2) at 2 um, (9, 2) at 1.5 um, (0, 3) and (9, 3) at 1 um, 0 elsewhere.
  // Levels 2, 1.5, 1, 0 um: 0, 1, 2, 4 points; the two halves touch only across the seam in x.
  HeightMap h = HeightMap::Zero(6, 10);
  h(2, 0) = 2 * um;
  h(2, 9) = 1.5 * um;
  h(3, 0) = h(3, 9) = 1 * um;
  const Surface s = from_heights(h, true);
  for (const Connectivity con : {Connectivity::four, Connectivity::eight})
    for (const bool wrap : {false, true})
      for (const int threads : {1, 2}) {
        const Topology t{con, wrap, wrap};
        const SweepCurve c = sweep(s, SweepLevels::exact(), t, threads);
        EXPECT_EQ(c.z, (std::vector<Real>{2 * um, 1.5 * um, 1 * um, 0.0}));
        EXPECT_EQ(c.points, (std::vector<Index>{0, 1, 2, 4}));
        const std::vector<Index> spots =
            wrap ? std::vector<Index>{0, 1, 1, 1} : std::vector<Index>{0, 1, 2, 2};
        EXPECT_EQ(c.spots, spots) << describe(t) << ", threads " << threads;
      }
  // The same across the seam in y (rows 0 and ny - 1 = 9), which also crosses the 2-thread stripes.
  const HeightMap ht = h.transpose();  // 6 x 10 -> 10 rows x 6 columns: the seam is now in y
  const Surface sy = from_heights(ht, true);
  for (const Connectivity con : {Connectivity::four, Connectivity::eight})
    for (const int threads : {1, 2}) {
      EXPECT_EQ(sweep(sy, SweepLevels::exact(), {con, false, true}, threads).spots,
                (std::vector<Index>{0, 1, 1, 1}));
      EXPECT_EQ(sweep(sy, SweepLevels::exact(), {con, true, false}, threads).spots,
                (std::vector<Index>{0, 1, 2, 2}));
    }
}

TEST(SweepHardCases, QuantisedHeightsWithWidePlateaus) {
  // Heights rounded to whole multiples of 0.5 um (about nine values over +- 2 sigma): wide plateaus of
  // equal heights. Ties must neither create nor lose a spot, so brute force must agree at every level, and
  // a point exactly at a level is not above it.
  for (int seed = 0; seed < 3; ++seed) {
    const Surface smooth = random_surface(32, 24, 500 + static_cast<std::uint64_t>(seed));
    const HeightMap q = (smooth.heights() / (0.5 * um)).round() * (0.5 * um);
    const Surface s = from_heights(q, true);
    for (const Topology& t : sweep_topologies()) {
      const SweepCurve c = sweep(s, SweepLevels::exact(), t, 1);
      expect_brute_force(s, c, t, what(s, t, "exact", 1) + ", quantised");
      expect_exact_levels(s, c, what(s, t, "exact", 1) + ", quantised");
      expect_identical(c, sweep(s, SweepLevels::exact(), t, 2), what(s, t, "exact", 2) + ", quantised");
    }
  }
  // Integer heights -3..3 (in units that make every level exact in floating point): uniform levels with
  // count 6 and paper levels with count 3 land exactly on the plateau heights, so every level is a tie.
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> level(-3, 3);
  HeightMap integer(20, 18);
  for (Index iy = 0; iy < integer.rows(); ++iy)
    for (Index ix = 0; ix < integer.cols(); ++ix)
      integer(iy, ix) = level(rng);
  integer(0, 0) = 3;  // make sure the extremes are present
  integer(1, 1) = -3;
  const Surface s = from_heights(integer);
  for (const Topology& t : sweep_topologies())
    for (const int threads : {1, 2}) {
      const SweepCurve exact = sweep(s, SweepLevels::exact(), t, threads);
      expect_brute_force(s, exact, t, what(s, t, "exact", threads) + ", integer");
      ASSERT_EQ(exact.z, (std::vector<Real>{3, 2, 1, 0, -1, -2, -3}));
      const SweepCurve uniform = sweep(s, SweepLevels::uniform(6), t, threads);
      expect_brute_force(s, uniform, t, what(s, t, "uniform", threads) + ", integer");
      // The same levels as the exact mode, bit for bit: max - j (max - min)/6 = 3 - j is exact in floating
      // point for these integers, so no round-off is allowed; the same levels must give the same sets.
      // (Before, points and spots were compared only when the levels happened to be bit-equal, so a level
      // off by one ulp, or a uniform mode that counted different sets, passed unseen.)
      ASSERT_EQ(uniform.z, exact.z) << what(s, t, "uniform", threads);
      EXPECT_EQ(uniform.points, exact.points) << what(s, t, "uniform", threads);
      EXPECT_EQ(uniform.spots, exact.spots) << what(s, t, "uniform", threads);
      const SweepCurve paper = sweep(s, SweepLevels::paper(3), t, threads);
      expect_brute_force(s, paper, t, what(s, t, "paper", threads) + ", integer");
    }
}

TEST(SweepHardCases, SingleRowAndSingleColumn) {
  for (int seed = 0; seed < 3; ++seed)
    for (const bool row : {true, false}) {
      const Surface s = row ? white_surface(40, 1, 60 + static_cast<std::uint64_t>(seed))
                            : white_surface(1, 40, 70 + static_cast<std::uint64_t>(seed));
      for (const Connectivity con : {Connectivity::four, Connectivity::eight})
        for (const bool wx : {false, true})
          for (const bool wy : {false, true}) {
            const Topology t{con, wx, wy};
            const SweepCurve c = sweep(s, SweepLevels::exact(), t, 1);
            expect_brute_force(s, c, t, what(s, t, "exact", 1));
            expect_exact_levels(s, c, what(s, t, "exact", 1));
            expect_identical(c, sweep(s, SweepLevels::exact(), t, 2), what(s, t, "exact", 2));
            const SweepCurve u = sweep(s, SweepLevels::uniform(13), t, 1);
            expect_brute_force(s, u, t, what(s, t, "uniform", 1));
          }
    }
  // A single point: one level (its height), nothing above it.
  const Surface one = from_heights(HeightMap::Constant(1, 1, 0.5 * um));
  const SweepCurve c = sweep(one, SweepLevels::exact(), {Connectivity::eight, true, true}, 2);
  EXPECT_EQ(c.z, (std::vector<Real>{0.5 * um}));
  EXPECT_EQ(c.points, (std::vector<Index>{0}));
  EXPECT_EQ(c.spots, (std::vector<Index>{0}));
}

TEST(SweepHardCases, NoLevelAboveTheMaximumAndTheMinimumIsTheLastExactLevel) {
  // The minimum appears on several points: at the last exact level they are the only points not above.
  HeightMap h(4, 5);
  h << 2, 1, 0, 1, 2,   //
      1, -1, -1, 0, 3,  //
      0, -1, 2, 2, 1,   //
      3, 1, 0, -1, 0;
  h *= um;
  const Surface s = from_heights(h);
  for (const Topology& t : sweep_topologies()) {
    const SweepCurve exact = sweep(s, SweepLevels::exact(), t, 1);
    expect_brute_force(s, exact, t, what(s, t, "exact", 1));
    EXPECT_EQ(exact.z.front(), 3 * um);
    EXPECT_EQ(exact.z.back(), -1 * um);
    EXPECT_EQ(exact.points.back(), 20 - 4);
    for (const SweepLevels levels : {SweepLevels::exact(), SweepLevels::uniform(8), SweepLevels::paper(6)}) {
      const SweepCurve c = sweep(s, levels, t, 2);
      for (const Real z : c.z)
        EXPECT_LE(z, 3 * um) << describe(t);  // nothing above the maximum
      EXPECT_EQ(c.z.front(), 3 * um);
      EXPECT_EQ(c.points.front(), 0);
    }
    // Uniform levels end at the minimum (to round-off), where the four minimum points are not above.
    const SweepCurve u = sweep(s, SweepLevels::uniform(8), t, 1);
    EXPECT_NEAR(u.z.back(), -1 * um, 1e-12 * um);
    expect_brute_force(s, u, t, what(s, t, "uniform", 1));
    if (u.z.back() == -1 * um) {
      EXPECT_EQ(u.points.back(), 16);
    }
  }
}

}  // namespace
}  // namespace contactbench
