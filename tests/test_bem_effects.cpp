// The Polonsky-Keer solver's options beyond the elastic load-controlled contact (bem/bem_solver.hpp): a
// perfectly plastic pressure cap (hardness), checked in its two limits (very hard: elastic; very soft: the
// bearing area) and on a sphere; separation control, against load control and Hertz's approach; single
// precision, against double; and the options of `contactbench bem` that reach them, end to end. First, the
// convolution engine under them (bem/convolution.hpp) through what the solver relies on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include "contact_shapes.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/convolution.hpp"
#include "contactbench/bem/half_space.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/topography_io.hpp"
#include "csv_rows.hpp"
#include "each_solver.hpp"
#include "reference_solutions.hpp"
#include "test_constants.hpp"

namespace contactbench {
namespace {

class Hardness : public EachSolver {};
class Separation : public EachSolver {};
class SinglePrecision : public EachSolver {};

// A random rough surface: the paper's surface A spectrum on n x n points over 100 um (seeded).
Surface rough_surface(Index n, bool periodic) {
  const Grid grid{.nx = n, .ny = n, .lx = 100e-6, .ly = 100e-6, .periodic = true};
  return generate_surface(grid, paper::surface_a(), 7).with_periodic(periodic);
}

HeightMap lcg_pressure(Index nx, Index ny, unsigned seed) {
  HeightMap p(ny, nx);
  std::uint64_t state = seed;
  for (Index i = 0; i < p.size(); ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;  // Knuth's LCG: enough for a test
    p.data()[i] = 1e8 * static_cast<Real>(state >> 11) / static_cast<Real>(1ULL << 53);
  }
  return p;
}

TEST(Convolution, PlainArraysInPlaceAndTheProductAgreeWithTheOperator) {
  // Odd and even sizes, both operators: the copy-free apply on plain arrays (also in place) equals the
  // HeightMap apply bit for bit (the same arithmetic); the product returned by the callback apply is
  // p . G p, summed in the spectral domain, equal to the direct sum to round-off; float agrees with double
  // to float's accuracy.
  for (const bool periodic : {true, false})
    for (const auto& [nx, ny] : {std::pair<Index, Index>{12, 9}, std::pair<Index, Index>{40, 32}}) {
      const Grid grid{.nx = nx, .ny = ny, .lx = nx * 1e-6, .ly = ny * 1.5e-6, .periodic = periodic};
      const HeightMap p = lcg_pressure(nx, ny, 3);
      auto half_space = make_half_space(grid, testing::kPaperModulus);
      HeightMap u;
      half_space->apply(p, u);
      HeightMap raw(ny, nx), in_place = p;
      half_space->apply(p.data(), raw.data());
      half_space->apply(in_place.data(), in_place.data());
      EXPECT_EQ((raw - u).abs().maxCoeff(), 0) << periodic << " " << nx;
      EXPECT_EQ((in_place - u).abs().maxCoeff(), 0) << periodic << " " << nx;

      auto convolution = make_half_space_convolution<double>(grid, testing::kPaperModulus);
      // The width by value: a lambda may not capture a structured binding before C++20 as clang 14 has it.
      auto produce = [&, width = nx](Index first, Index rows, double* buffer, Index ld, int) {
        for (Index r = 0; r < rows; ++r)
          for (Index x = 0; x < width; ++x)
            buffer[r * ld + x] = p(first + r, x);
      };
      const double product = convolution->apply(Convolution<double>::Producer(produce),
                                                Convolution<double>::Consumer(), {}, true);
      const Real direct = (p * u).sum();
      EXPECT_NEAR(product, direct, 1e-12 * direct) << periodic << " " << nx;

      auto single = make_half_space_convolution<float>(grid, testing::kPaperModulus);
      std::vector<float> pf(p.data(), p.data() + p.size()), uf(pf.size());
      single->apply(pf.data(), uf.data());
      Real worst = 0;
      for (Index i = 0; i < p.size(); ++i)
        worst = std::max(worst, std::abs(static_cast<Real>(uf[static_cast<std::size_t>(i)]) - u.data()[i]));
      EXPECT_LT(worst, 1e-6 * u.abs().maxCoeff()) << periodic << " " << nx;  // float: ~1e-7, summed
    }
}

TEST(Convolution, ManyThreadsGiveTheSameAnswerAsOne) {
  // Above kMinPointsForThreads the team has two threads; the chunks are fixed, so the result is the same
  // bit for bit whatever the team.
  const Grid grid{.nx = 256, .ny = 256, .lx = 256e-6, .ly = 256e-6, .periodic = true};
  const HeightMap p = lcg_pressure(256, 256, 5);
  HeightMap one, two;
  make_half_space(grid, testing::kPaperModulus, 1)->apply(p, one);
  make_half_space(grid, testing::kPaperModulus, 2)->apply(p, two);
  EXPECT_EQ((one - two).abs().maxCoeff(), 0);
}

TEST_P(Hardness, VeryHardReproducesTheElasticSolution) {
  // A cap far above every elastic pressure changes nothing: the elastic solution is the answer, to the
  // solver's tolerance. Both operators, and a cap just above the largest elastic pressure too.
  for (const bool periodic : {true, false}) {
    const Surface surface = rough_surface(64, periodic);
    const Real load = 0.02 * testing::kPaperModulus * 0.05;  // P/A0: a few percent of contact
    BemSolver elastic(surface, testing::kPaperModulus, {.tolerance = 1e-10, .solver = GetParam()});
    const ContactSolution reference = elastic.solve(load);
    ASSERT_TRUE(reference.converged);
    const Real largest = reference.pressure.maxCoeff();
    for (const Real factor : {1e6, 1.001}) {
      BemSolver capped(surface, testing::kPaperModulus,
                       {.tolerance = 1e-10, .hardness = factor * largest, .solver = GetParam()});
      const ContactSolution& s = capped.solve(load);
      ASSERT_TRUE(s.converged) << periodic << " " << factor;
      EXPECT_EQ(s.plastic_points, 0);
      EXPECT_EQ(s.contact_points, reference.contact_points);
      EXPECT_LT((s.pressure - reference.pressure).abs().maxCoeff(), 1e-9 * largest);
      EXPECT_NEAR(s.separation, reference.separation, 1e-9 * surface.heights().maxCoeff());
    }
  }
}

TEST_P(Hardness, CapJustBelowThePeakIsCloseToElastic) {
  // A cap at 99 % of the largest elastic pressure (met by a search on the flat's height with capped solves,
  // or by active_set's plastic set): the peak becomes plastic and the rest barely moves (measured: one
  // plastic point, the same contact count; allow 0.5 % of it).
  const Surface surface = rough_surface(64, true);
  const Real load = 0.02 * testing::kPaperModulus * 0.05;
  BemSolver elastic(surface, testing::kPaperModulus, {.tolerance = 1e-10, .solver = GetParam()});
  const ContactSolution reference = elastic.solve(load);
  const Real hardness = 0.99 * reference.pressure.maxCoeff();
  BemSolver capped(surface, testing::kPaperModulus,
                   {.tolerance = 1e-10, .hardness = hardness, .solver = GetParam()});
  const ContactSolution& s = capped.solve(load);
  ASSERT_TRUE(s.converged);
  EXPECT_GT(s.plastic_points, 0);
  EXPECT_LE(s.pressure.maxCoeff(), hardness);
  EXPECT_NEAR(s.pressure.mean(), load, 1e-12 * load);  // imposed exactly at the end
  EXPECT_NEAR(static_cast<Real>(s.contact_points), static_cast<Real>(reference.contact_points),
              0.005 * static_cast<Real>(reference.contact_points));
  EXPECT_LT(s.residual, 1e-8);
}

TEST(ActiveSetHardness, ACappedLoadIsOneSolveNotASearch) {
  // active_set meets a hardness within its own solve (a plastic set, bem/active_set.hpp), where plain
  // Polonsky-Keer solves elastically and then searches the flat's height with capped solves under separation
  // control. A rough surface on 128 x 128 points with H at half the elastic peak pressure, load 2 % of E* x
  // slope 0.05: both give the same sets (the counts exactly: the solutions agree to 1e-10) and pressures
  // (1e-8 relative L2, the tolerance's order), and at most half the iterations: measured 54 against 158
  // (periodic) and 55 against 156 (zero-padded); a search alone costs three capped solves or more.
  for (const bool periodic : {true, false}) {
    const Surface surface = rough_surface(128, periodic);
    const Real load = 0.02 * testing::kPaperModulus * 0.05;
    BemSolver elastic(surface, testing::kPaperModulus,
                      {.tolerance = 1e-10, .solver = SolverKind::active_set});
    const Real hardness = 0.5 * elastic.solve(load).pressure.maxCoeff();
    auto capped = [&](SolverKind solver) {
      BemSolver capped_solver(surface, testing::kPaperModulus,
                              {.tolerance = 1e-10, .hardness = hardness, .solver = solver});
      return capped_solver.solve(load);
    };
    const ContactSolution plain = capped(SolverKind::polonsky_keer);
    const ContactSolution active = capped(SolverKind::active_set);
    ASSERT_TRUE(plain.converged && active.converged) << periodic;
    EXPECT_GT(active.plastic_points, 0) << periodic;
    EXPECT_EQ(active.plastic_points, plain.plastic_points) << periodic;
    EXPECT_EQ(active.contact_points, plain.contact_points) << periodic;
    EXPECT_LT((active.pressure - plain.pressure).matrix().norm(), 1e-8 * plain.pressure.matrix().norm())
        << periodic;
    EXPECT_LE(2 * active.iterations, plain.iterations) << active.iterations << " vs " << plain.iterations;
  }
}

TEST_P(Hardness, VerySoftTendsToTheBearingArea) {
  // H far below the elastic contact pressures (1e-4 of the largest): the displacements H dx/E* are far
  // smaller than the spacing of the heights, so the contact is the bearing area: P/H of the area, and the
  // set {h > d} of the highest points. Load P/A0 = 0.2 H: 20 % of the points.
  for (const bool periodic : {true, false}) {
    const Index n = 64;
    const Surface surface = rough_surface(n, periodic);
    const Real scale = 0.05 * testing::kPaperModulus;  // pressures of the elastic contact: E* times a slope
    const Real hardness = 1e-4 * scale, load = 0.2 * hardness;
    BemSolver solver(surface, testing::kPaperModulus,
                     {.tolerance = 1e-10, .hardness = hardness, .solver = GetParam()});
    const ContactSolution& s = solver.solve(load);
    ASSERT_TRUE(s.converged) << periodic;
    const Index points = n * n;
    // Area: all but the few elastic points are at H, so the contact is P/H of the area up to those few
    // (measured: 1 elastic point of 820, both operators); allow 4 points, 0.1 % of the area.
    const Real fraction = static_cast<Real>(s.contact_points) / static_cast<Real>(points);
    EXPECT_NEAR(fraction, load / hardness, 4.0 / static_cast<Real>(points)) << periodic;
    EXPECT_GE(s.plastic_points, s.contact_points - 4) << periodic;
    EXPECT_NEAR(s.pressure.mean(), load, 1e-12 * load);
    // The set: the k highest points, k = the contact count. The displacements (at most H times the contact's
    // size over E*, 2e-10 m, and smooth) could only swap points whose heights differ by less than their
    // differences; the heights about the level are 1.3e-10 m apart (measured: 0 mismatches); allow 2 points.
    const HeightMap& h = solver.surface().heights();
    std::vector<Real> sorted(h.data(), h.data() + h.size());
    std::sort(sorted.begin(), sorted.end(), std::greater<>());
    const Real level = sorted[static_cast<std::size_t>(s.contact_points) - 1];  // lowest point inside
    Index mismatches = 0;
    for (Index i = 0; i < points; ++i)
      mismatches += (s.pressure.data()[i] > 0) != (h.data()[i] >= level);
    EXPECT_LE(mismatches, 2) << periodic;
  }
}

TEST_P(Hardness, SphereBelowItsHertzPeakIsCappedAndWider) {
  // Hertz: a = 32 pixels, p0 = 3P/(2 pi a^2). With H = 0.7 p0 the pressure is flat at H in a plastic core,
  // the contact is wider than Hertz's, and at least P/H in area (p <= H everywhere).
  const Index n = 128;
  const Real dx = 1e-6, radius = 1e-3, a = 32 * dx;
  const reference::HertzSphere hertz{.radius = radius, .modulus = testing::kPaperModulus};
  const Real load = hertz.load_of_contact_radius(a), hardness = 0.7 * hertz.peak_pressure(load);
  const Surface surface = sphere(n, dx, radius);
  const Real area = surface.grid().nominal_area();
  BemSolver solver(surface, testing::kPaperModulus,
                   {.tolerance = 1e-10, .hardness = hardness, .solver = GetParam()});
  const ContactSolution& s = solver.solve(load / area);
  ASSERT_TRUE(s.converged) << s.iterations;
  EXPECT_LE(s.pressure.maxCoeff(), hardness);
  EXPECT_EQ(s.pressure.maxCoeff(), hardness);  // the core sits at H exactly
  EXPECT_GT(s.plastic_points, 0);
  const Real contact_area = static_cast<Real>(s.contact_points) * dx * dx;
  EXPECT_GT(contact_area, load / hardness);
  // Wider than Hertz by more than the half-pixel resolution of the edge (1.6 % of a; measured: +4.0 %).
  const Real contact_radius = std::sqrt(contact_area / pi);
  EXPECT_GT(contact_radius, 1.03 * a);
  EXPECT_NEAR(s.pressure.sum() * dx * dx, load, 1e-12 * load);
  EXPECT_LT(s.residual, 1e-8);
  // The plastic core is a disc at the centre: the apex is plastic.
  EXPECT_EQ(s.pressure(n / 2, n / 2), hardness);
}

TEST_P(Hardness, RefusesFullPlasticContactAndABadHardness) {
  const Surface surface = rough_surface(16, true);
  BemSolver solver(surface, testing::kPaperModulus, {.hardness = 1e9, .solver = GetParam()});
  EXPECT_THROW(solver.solve(1e9), Error);  // P/A0 = H: full plastic contact
  EXPECT_THROW(solver.solve(2e9), Error);
  EXPECT_THROW(BemSolver(surface, testing::kPaperModulus, {.hardness = 0.0, .solver = GetParam()}), Error);
  EXPECT_THROW(BemSolver(surface, testing::kPaperModulus, {.hardness = -1.0, .solver = GetParam()}), Error);
  EXPECT_THROW(BemSolver(surface, testing::kPaperModulus, {.hardness = std::nan(""), .solver = GetParam()}),
               Error);
}

TEST_P(Separation, GivesBackTheLoadThatLoadControlFound) {
  // Load control at P/A0 reports the flat's height d; a cold solve for that d must carry P/A0 again. Both
  // converge to a relative pressure change of 1e-12, which fixes the pressure, hence d and the load, to
  // about that relative accuracy times the conditioning of the contact (a few hundred at most here): 1e-6
  // is a wide bound (measured: 6e-15 periodic, 3e-14 not), and the contact sets must be the same.
  for (const bool periodic : {true, false}) {
    const Surface surface = rough_surface(64, periodic);
    const Real load = 0.02 * testing::kPaperModulus * 0.05;
    BemSolver by_load(surface, testing::kPaperModulus, {.tolerance = 1e-12, .solver = GetParam()});
    const ContactSolution reference = by_load.solve(load);
    ASSERT_TRUE(reference.converged);
    BemSolver by_separation(surface, testing::kPaperModulus, {.tolerance = 1e-12, .solver = GetParam()});
    const ContactSolution& s = by_separation.solve_for_separation(reference.separation);
    ASSERT_TRUE(s.converged) << periodic;
    EXPECT_NEAR(s.mean_pressure, load, 1e-6 * load) << periodic;
    EXPECT_NEAR(s.pressure.mean(), s.mean_pressure, 1e-12 * load);
    EXPECT_EQ(s.separation, reference.separation);
    EXPECT_EQ(s.contact_points, reference.contact_points) << periodic;
    EXPECT_LT((s.pressure - reference.pressure).abs().maxCoeff(), 1e-6 * reference.pressure.maxCoeff());
    EXPECT_LT(s.residual, 1e-10);
    // Warm: the same solver asked back for its own d converges at once to the same load.
    const ContactSolution& again = by_load.solve_for_separation(reference.separation);
    EXPECT_NEAR(again.mean_pressure, load, 1e-6 * load) << periodic;
  }
}

TEST_P(Separation, HertzLoadOfAnApproach) {
  // The sphere of BemSolver.HertzContactOfASphere: the approach delta = a^2/R of the apex (a = 32 pixels)
  // must carry P = 4 E* a^3/(3 R). The load is an integral of the pressure, whose discretisation error is
  // of order (dx/a)^2 ~ 1e-3 (load control measured the approach to below 1e-4); P ~ delta^(3/2): allow
  // 3e-3 (measured: 5e-5).
  const Index n = 128;
  const Real dx = 1e-6, radius = 1e-3, a = 32 * dx;
  const Surface surface = sphere(n, dx, radius);
  BemSolver solver(surface, testing::kPaperModulus,
                   {.tolerance = 1e-12, .max_iterations = 5000, .solver = GetParam()});
  const Real apex = solver.surface().heights().maxCoeff();
  const reference::HertzSphere hertz{.radius = radius, .modulus = testing::kPaperModulus};
  const Real load = hertz.load_of_contact_radius(a);
  const ContactSolution& s = solver.solve_for_separation(apex - hertz.approach(load));
  ASSERT_TRUE(s.converged) << s.iterations;
  EXPECT_NEAR(s.mean_pressure * surface.grid().nominal_area(), load, 3e-3 * load);
  const Real radius_from_nodes = std::sqrt(static_cast<Real>(s.contact_points) * dx * dx / pi);
  EXPECT_NEAR(radius_from_nodes, a, 0.016 * a);  // the edge to half a pixel, as under load control
  EXPECT_LT(s.residual, 1e-8);
}

TEST_P(Separation, WithHardnessGivesBackTheCappedLoad) {
  // The capped sphere (H = 0.7 p0): load control finds the flat's height; solving for the height it
  // found carries the load again, with the same plastic core (tolerance as in the elastic case; measured:
  // 7e-14).
  const Index n = 128;
  const Real dx = 1e-6, radius = 1e-3, a = 32 * dx;
  const reference::HertzSphere hertz{.radius = radius, .modulus = testing::kPaperModulus};
  const Real load = hertz.load_of_contact_radius(a), hardness = 0.7 * hertz.peak_pressure(load);
  const Surface surface = sphere(n, dx, radius);
  const Real mean = load / surface.grid().nominal_area();
  BemSolver by_load(surface, testing::kPaperModulus,
                    {.tolerance = 1e-12, .hardness = hardness, .solver = GetParam()});
  const ContactSolution reference = by_load.solve(mean);
  ASSERT_TRUE(reference.converged);
  BemSolver by_separation(surface, testing::kPaperModulus,
                          {.tolerance = 1e-12, .hardness = hardness, .solver = GetParam()});
  const ContactSolution& s = by_separation.solve_for_separation(reference.separation);
  ASSERT_TRUE(s.converged);
  EXPECT_NEAR(s.mean_pressure, mean, 1e-6 * mean);
  EXPECT_EQ(s.plastic_points, reference.plastic_points);
  EXPECT_EQ(s.contact_points, reference.contact_points);
}

TEST_P(Separation, AboveTheSurfaceNothingAndPeriodicNeedsAPositiveMeanGap) {
  const Surface surface = rough_surface(32, true);
  BemSolver solver(surface, testing::kPaperModulus, {.solver = GetParam()});
  const Real top = solver.surface().heights().maxCoeff();
  const ContactSolution& s = solver.solve_for_separation(top);
  EXPECT_TRUE(s.converged);
  EXPECT_EQ(s.contact_points, 0);
  EXPECT_EQ(s.mean_pressure, 0);
  EXPECT_GE(s.gap.minCoeff(), 0);
  // Periodic: d is the mean gap, which no finite load brings to zero or below.
  EXPECT_THROW(solver.solve_for_separation(0), Error);
  EXPECT_THROW(solver.solve_for_separation(-1e-7), Error);
  EXPECT_THROW(solver.solve_for_separation(std::nan("")), Error);
  // Non-periodic: any height. Ten height ranges below the lowest point the window is pressed in like a
  // punch, whose displacement dwarfs the roughness: full contact, at a finite load. (One range below is
  // not enough: a punch sinks deeper at its centre than at its edges, and lifts off there; measured 726 of
  // 1024 points, load control at the same load agreeing.)
  BemSolver window(rough_surface(32, false), testing::kPaperModulus,
                   {.tolerance = 1e-10, .solver = GetParam()});
  const Real bottom = window.surface().heights().minCoeff();
  const ContactSolution& full = window.solve_for_separation(bottom - 10 * (top - bottom));
  EXPECT_TRUE(full.converged);
  EXPECT_EQ(full.contact_points, 32 * 32);
  EXPECT_GT(full.mean_pressure, 0);
}

TEST_P(SinglePrecision, AgreesWithDoubleToFloatsAccuracy) {
  // A 128 x 128 random surface at P/A0 = 0.01 E* (11 % of contact), both operators: float at the smallest
  // tolerance it accepts against double at 1e-10. Float's gap is good to about 1e-7 of the heights, so
  // the area fraction (node count) may differ by points whose gap is that close to zero, a few in 1e3 at
  // most: 1e-3 relative; the mean gap and the flat's height, integrals, to 1e-4 relative (measured:
  // identical counts, mean gaps within 2e-7).
  for (const bool periodic : {true, false}) {
    const Surface surface = rough_surface(128, periodic);
    const Real load = 0.01 * testing::kPaperModulus;
    BemSolver twice(surface, testing::kPaperModulus, {.tolerance = 1e-10, .solver = GetParam()});
    const ContactSolution reference = twice.solve(load);
    BemSolver single(
        surface, testing::kPaperModulus,
        {.tolerance = kSinglePrecisionTolerance, .single_precision = true, .solver = GetParam()});
    const ContactSolution& s = single.solve(load);
    ASSERT_TRUE(s.converged) << periodic;  // float reaches its tolerance
    EXPECT_LT(s.change, kSinglePrecisionTolerance);
    const Real points = static_cast<Real>(reference.contact_points);
    EXPECT_NEAR(static_cast<Real>(s.contact_points), points, 1e-3 * points) << periodic;
    EXPECT_NEAR(s.gap.mean(), reference.gap.mean(), 1e-4 * reference.gap.mean()) << periodic;
    EXPECT_NEAR(s.separation, reference.separation, 1e-4 * std::abs(reference.separation)) << periodic;
    EXPECT_NEAR(s.pressure.mean(), load, 1e-6 * load);  // float sums, imposed to float's accuracy
    EXPECT_LT(s.residual, 1e-6);
  }
}

TEST_P(SinglePrecision, CappedAndSeparationControlledToo) {
  // The other modes in float: the capped sphere (as Hardness.SphereBelowItsHertzPeakIsCappedAndWider) and
  // the Hertz approach (as Separation.HertzLoadOfAnApproach), at float's tolerance.
  const Index n = 128;
  const Real dx = 1e-6, radius = 1e-3, a = 32 * dx;
  const reference::HertzSphere hertz{.radius = radius, .modulus = testing::kPaperModulus};
  const Real load = hertz.load_of_contact_radius(a);
  const Surface surface = sphere(n, dx, radius);
  const Real area = surface.grid().nominal_area();
  // Twice: H = 0.7 p0 as it comes, and H a quarter of a float step above a float value, so that float rounds
  // it down. Plastic nodes hold float(H), below the double H there, and every test p >= H must compare with
  // the value held: compared with the double H, polonsky_keer's and preconditioned_cg's plastic nodes counted
  // as elastic (no plastic node, a residual of 0.24 of the height range, not converged).
  const Real given = 0.7 * hertz.peak_pressure(load);
  const float held = static_cast<float>(given);
  const Real rounds_down =
      static_cast<Real>(held) +
      0.25 * (static_cast<Real>(std::nextafter(held, 2 * held)) - static_cast<Real>(held));
  ASSERT_LT(static_cast<Real>(static_cast<float>(rounds_down)), rounds_down);
  for (const Real hardness : {given, rounds_down}) {
    BemSolver capped(surface, testing::kPaperModulus,
                     {.tolerance = kSinglePrecisionTolerance,
                      .hardness = hardness,
                      .single_precision = true,
                      .solver = GetParam()});
    const ContactSolution& s = capped.solve(load / area);
    ASSERT_TRUE(s.converged) << hardness << ": residual " << s.residual;
    EXPECT_LE(s.pressure.maxCoeff(), hardness * (1 + 1e-6));  // H rounded to float
    EXPECT_GT(s.plastic_points, 0) << hardness;
    EXPECT_NEAR(s.pressure.mean() * area, load, 1e-5 * load);
  }
  BemSolver elastic(surface, testing::kPaperModulus,
                    {.tolerance = kSinglePrecisionTolerance, .single_precision = true, .solver = GetParam()});
  const Real apex = elastic.surface().heights().maxCoeff();
  const ContactSolution& e = elastic.solve_for_separation(apex - hertz.approach(load));
  ASSERT_TRUE(e.converged);
  EXPECT_NEAR(e.mean_pressure * area, load, 3e-3 * load);
}

TEST_P(SinglePrecision, RefusesATolerancePastFloat) {
  const Surface surface = rough_surface(16, true);
  EXPECT_THROW(BemSolver(surface, testing::kPaperModulus,
                         {.tolerance = 1e-7, .single_precision = true, .solver = GetParam()}),
               Error);
  EXPECT_NO_THROW(BemSolver(surface, testing::kPaperModulus,
                            {.tolerance = 1e-6, .single_precision = true, .solver = GetParam()}));
  EXPECT_NO_THROW(
      BemSolver(surface, testing::kPaperModulus, {.tolerance = 1e-7, .solver = GetParam()}));  // double: fine
}

// `contactbench bem` run as a user would (the binary the build made), in a folder of its own.
class BemCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ =
        std::filesystem::temp_directory_path() /
        ("contactbench_bem_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
    surface_ = folder_ / "s.txt";
    write_surface(surface_, rough_surface(64, true));
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  // Exit status and standard error of `contactbench bem <surface> <arguments>`.
  std::pair<int, std::string> bem(const std::string& arguments) {
    const auto err = folder_ / "stderr.txt";
    const std::string command = std::string(CB_CLI_PATH) + " bem " + surface_.string() + " " + arguments +
                                " >/dev/null 2>" + err.string() + " </dev/null";
    const int raw = std::system(command.c_str());
    std::ifstream in(err);
    std::stringstream text;
    text << in.rdbuf();
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text.str()};
  }

  // The CSV's rows by column name (the curves.csv of a one-method scene, app/report_writers.hpp); the
  // column names in `header`.
  std::vector<CsvRow> rows(const std::filesystem::path& csv, std::vector<std::string>& header) {
    std::ifstream in(csv);
    std::stringstream text;
    text << in.rdbuf();
    return csv_rows(text.str(), header);
  }

  std::filesystem::path folder_, surface_;
};

TEST_F(BemCommand, HardnessFloatAndFields) {
  // E* = 109.9 GPa; loads 0.002 and 0.005 E* (0.22 and 0.55 GPa) under H = 2 GPa: capped, in float.
  const auto csv = folder_ / "bem.csv";
  const std::string prefix = (folder_ / "f").string();
  const auto [status, err] =
      bem("--loads 0.005,0.002 --hardness 2e9 --float --fields " + prefix + " --out " + csv.string());
  ASSERT_EQ(status, 0) << err;
  std::vector<std::string> header;
  const auto table = rows(csv, header);
  EXPECT_NE(std::find(header.begin(), header.end(), "plastic_area_fraction"), header.end());
  ASSERT_EQ(table.size(), 2u);
  const auto number = [&](std::size_t k, const char* column) { return std::stod(table[k].at(column)); };
  for (std::size_t k = 0; k < table.size(); ++k) {
    EXPECT_EQ(table[k].at("converged"), "1");
    EXPECT_LE(number(k, "max_pressure"), 2e9 * (1 + 1e-6));
    // The fields of row k (the loads in increasing order), read back with their grid.
    // The pressure field says its unit (Pa), so it reads as a field, not as heights.
    const Field pressure_field = read_field(prefix + "_load" + std::to_string(k + 1) + "_pressure.txt");
    EXPECT_EQ(pressure_field.unit, "Pa");
    const Surface& pressure = pressure_field.values;
    const Surface gap = read_topography(prefix + "_load" + std::to_string(k + 1) + "_gap.txt");
    EXPECT_EQ(pressure.grid().nx, 64);
    EXPECT_TRUE(pressure.grid().periodic);
    const Real load = number(k, "load") * 1e11 / (1 - 0.3 * 0.3);
    EXPECT_NEAR(pressure.heights().mean(), load, 1e-5 * load);  // float's load, imposed
    EXPECT_NEAR(gap.heights().mean(), number(k, "mean_gap"), 1e-6 * number(k, "mean_gap"));
    // plastic_area_fraction = nodes at p = H / all nodes (exact in double: a count over 64^2).
    EXPECT_EQ(number(k, "plastic_area_fraction") * 64 * 64,
              static_cast<Real>((pressure.heights() >= 2e9 * (1 - 1e-7)).count()));
  }
  EXPECT_LT(number(0, "load"), number(1, "load"));
  EXPECT_GT(number(1, "plastic_area_fraction"), 0);  // the larger load has plastic points
}

TEST_F(BemCommand, WithoutHardnessNoPlasticColumn) {
  const auto csv = folder_ / "bem.csv";
  ASSERT_EQ(bem("--loads 0.002 --out " + csv.string()).first, 0);
  std::vector<std::string> header;
  const auto table = rows(csv, header);
  EXPECT_EQ(std::find(header.begin(), header.end(), "plastic_area_fraction"), header.end());
  ASSERT_EQ(table.size(), 1u);
  EXPECT_EQ(table[0].size(), header.size());
}

TEST_F(BemCommand, RecordsTheSolverAndRefusesAnUnknownOne) {
  for (const std::string& name : solver_names()) {
    const auto csv = folder_ / ("bem_" + name + ".csv");
    ASSERT_EQ(bem("--loads 0.002 --solver " + name + " --out " + csv.string()).first, 0);
    // The method's line in the CSV's header comments says which solver ran.
    std::ifstream in(csv);
    std::string line, method_line;
    while (std::getline(in, line) && line.starts_with("#"))
      if (line.starts_with("# bem:")) method_line = line;
    EXPECT_NE(method_line.find("(" + name + ","), std::string::npos) << method_line;
  }
  const auto [status, err] = bem("--loads 0.002 --solver multigrid");
  EXPECT_NE(status, 0);
  EXPECT_NE(err.find("--solver"), std::string::npos) << err;
  for (const std::string& name : solver_names())
    EXPECT_NE(err.find(name), std::string::npos) << err;
}

TEST_F(BemCommand, RefusesWhatCannotBeSolved) {
  // Float cannot reach 1e-8; a load at the hardness is full plastic contact; H must be positive.
  const auto [float_status, float_err] = bem("--loads 0.002 --float --tolerance 1e-8");
  EXPECT_NE(float_status, 0);
  EXPECT_NE(float_err.find("--tolerance"), std::string::npos) << float_err;
  const auto [plastic_status, plastic_err] = bem("--loads 0.002,0.01 --hardness 1e9");
  EXPECT_NE(plastic_status, 0);
  EXPECT_NE(plastic_err.find("full plastic"), std::string::npos) << plastic_err;
  const auto [zero_status, zero_err] = bem("--loads 0.002 --hardness 0");
  EXPECT_NE(zero_status, 0);
  EXPECT_NE(zero_err.find("--hardness"), std::string::npos) << zero_err;
}

CB_FOR_EACH_SOLVER(Hardness);
CB_FOR_EACH_SOLVER(Separation);
CB_FOR_EACH_SOLVER(SinglePrecision);

}  // namespace
}  // namespace contactbench
