// The BEM reference's error bar (bem/grid_convergence.hpp; docs/theory.md section 9.2): Roache's
// grid convergence index and the calibrated bar on exact power-law sequences, their fallbacks, and on the
// calibration study's hardest cases (scripts/studies/error_bar.py) that their bars cover the study's truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/grid_convergence.hpp"
#include "contactbench/core/generation.hpp"

namespace contactbench {
namespace {

// f(h) = exact + c h^p on h = 4, 2, 1 (grids n, 2n, 4n).
GridConvergence on_power_law(Real exact, Real c, Real p) {
  return grid_convergence_three(exact + c * std::pow(4.0, p), exact + c * std::pow(2.0, p), exact + c);
}

TEST(GridConvergence, AtTheFormalOrderRecoversTheLimitWithFactorOneQuarter) {
  const GridConvergence g = on_power_law(0.2, 0.01, 1.0);
  // Tolerance 1e-12: exact arithmetic up to a few roundings of numbers of order 0.2.
  EXPECT_NEAR(g.order, 1.0, 1e-10);
  EXPECT_NEAR(g.value, 0.2, 1e-12);
  EXPECT_EQ(g.factor, kGciFactorThreeGrids);
  EXPECT_EQ(g.grids, 3);
  // The fine grid's error is |f3 - f2|/(2^1 - 1) = c: the bar is 1.25 of it.
  EXPECT_NEAR(g.error, 1.25 * 0.01, 1e-12);
}

TEST(GridConvergence, AnOrderAwayFromTheFormalOneGetsTheFactorThree) {
  // Observed 0.6: used as observed (the limit exact), factor 3 on the fine grid's error c.
  const GridConvergence slow = on_power_law(0.2, 0.01, 0.6);
  EXPECT_NEAR(slow.order, 0.6, 1e-10);
  EXPECT_NEAR(slow.value, 0.2, 1e-12);
  EXPECT_EQ(slow.factor, kGciFactorTwoGrids);
  EXPECT_NEAR(slow.error, 3 * 0.01, 1e-12);
  // Observed 1.5 (what coarse grids show at small loads): extrapolated at the formal order 1, not 1.5, and
  // the factor 3; the bar still holds the exact limit.
  for (const Real p : {1.05, 1.5, 1.9}) {
    const GridConvergence fast = on_power_law(0.2, 0.01, p);
    EXPECT_NEAR(fast.order, p, 1e-10);
    EXPECT_EQ(fast.factor, p <= 1.1 ? kGciFactorThreeGrids : kGciFactorTwoGrids) << p;
    const Real d32 = 0.01 - 0.01 * std::pow(2.0, p);
    EXPECT_NEAR(fast.value, 0.21 + d32, 1e-12) << p;
    EXPECT_NEAR(fast.error, fast.factor * std::abs(d32), 1e-12) << p;
    EXPECT_LE(std::abs(fast.value - 0.2), fast.error) << p;
  }
}

TEST(GridConvergence, WithoutMonotoneConvergenceTheLargestChangeTimesThree) {
  // Observed order 3 (differences 0.08, 0.01): outside the asymptotic range; 3 x the larger difference.
  const GridConvergence steep = grid_convergence_three(0.39, 0.31, 0.30);
  EXPECT_NEAR(steep.order, 3.0, 1e-10);
  EXPECT_EQ(steep.factor, kGciFactorTwoGrids);
  EXPECT_NEAR(steep.error, 3 * 0.08, 1e-12);
  EXPECT_NEAR(steep.value, 0.29, 1e-12);
  // Oscillating: no order; the formal order 1 and the factor 3 on the larger difference (0.05).
  const GridConvergence oscillating = grid_convergence_three(0.30, 0.25, 0.27);
  EXPECT_TRUE(std::isnan(oscillating.order));
  EXPECT_EQ(oscillating.factor, kGciFactorTwoGrids);
  EXPECT_NEAR(oscillating.error, 3 * 0.05, 1e-12);  // tolerance: a few roundings of 0.05
  EXPECT_NEAR(oscillating.value, 0.29, 1e-12);
  // A flat last step after a change (a coarse grid's few contact nodes): the bar does not vanish.
  const GridConvergence flat_step = grid_convergence_three(0.0037, 0.0020, 0.0020);
  EXPECT_TRUE(std::isnan(flat_step.order));
  EXPECT_NEAR(flat_step.error, 3 * 0.0017, 1e-15);
  // Nothing changes at all: a zero bar is then the grids' honest answer.
  const GridConvergence flat = grid_convergence_three(0.5, 0.5, 0.5);
  EXPECT_EQ(flat.error, 0);
  EXPECT_EQ(flat.value, 0.5);
}

// The calibrated bar (error_estimate = "calibrated3", section 9.2) on f(h) = A0 + c h^p: the observed order
// is p exactly, the value the order-1 extrapolate, and the bar covers the exact limit A0 at every order the
// code trusts ([0.5, 2]) and in every load band, because it is at least the distance to the observed order's
// extrapolate (= A0).
TEST(GridConvergence, CalibratedRecoversTheOrderAndCoversAnExactPowerLaw) {
  constexpr Real kLimit = 0.2, kC = 0.01, kFinePoints = 256.0 * 256.0;
  for (const Real load : {1e-4, 1e-3, 1e-2}) {
    const Real k = load < kCalibratedLowLoadLimit    ? kCalibratedScaleFactorLow
                   : load > kCalibratedHighLoadLimit ? kCalibratedScaleFactorHigh
                                                     : kCalibratedScaleFactorMiddle;
    const Real lattice_factor = load < kCalibratedLowLoadLimit || load > kCalibratedHighLoadLimit
                                    ? 0
                                    : kCalibratedLatticeFactorMiddle;
    // Orders inside [0.5, 2] (at its ends the observed order's last rounding decides whether it is trusted).
    for (const Real p : {0.55, 0.7, 1.0, 1.3, 1.7, 1.95}) {
      const Real coarse = kLimit + kC * std::pow(4.0, p), medium = kLimit + kC * std::pow(2.0, p),
                 fine = kLimit + kC;
      const GridConvergence g = grid_convergence_calibrated(coarse, medium, fine, kFinePoints, load);
      // Tolerances 1e-10 (order, a log of a ratio of differences of numbers of order 0.2) and 1e-12 (values):
      // a few roundings.
      EXPECT_NEAR(g.order, p, 1e-10) << p;
      EXPECT_EQ(g.grids, 3);
      EXPECT_EQ(g.factor, k);
      EXPECT_NEAR(g.value, 2 * fine - medium, 1e-12) << p;
      // The bar is the largest of K x the scale, L x the lattice scatter sqrt(f3 / P3) and the order spread
      // |A0 - value| (the true error here).
      const Real d21 = medium - coarse, d32 = fine - medium;
      const Real scale = std::max({std::abs(d32), std::abs(d21) / 2, std::abs(2 * d32 - d21)});
      const Real true_error = std::abs(g.value - kLimit);
      EXPECT_NEAR(g.error, std::max({k * scale, lattice_factor * std::sqrt(fine / kFinePoints), true_error}),
                  1e-12)
          << p << " " << load;
      EXPECT_LE(true_error, g.error + 1e-12) << p;  // covered (up to the roundings above)
    }
  }
  // At the formal order the extrapolate is exact and the bar is K times the last step, c (high band: no
  // lattice term).
  const GridConvergence first = grid_convergence_calibrated(0.24, 0.22, 0.21, kFinePoints, 1e-2);
  EXPECT_NEAR(first.value, 0.2, 1e-12);
  EXPECT_NEAR(first.error, kCalibratedScaleFactorHigh * 0.01, 1e-12);
}

TEST(GridConvergence, CalibratedWithoutATrustedOrderIsTheFactorOnTheScale) {
  constexpr Real kFinePoints = 256.0 * 256.0, kLowLoad = 1e-4, kHighLoad = 5e-2;
  // Oscillating (differences -0.05, +0.02): no order; value 2 f3 - f2 = 0.29, scale max(0.02, 0.025, |0.04 +
  // 0.05|) = 0.09 (the order-1 extrapolate moved from 0.20 to 0.29).
  const GridConvergence oscillating = grid_convergence_calibrated(0.30, 0.25, 0.27, kFinePoints, kLowLoad);
  EXPECT_TRUE(std::isnan(oscillating.order));
  EXPECT_NEAR(oscillating.value, 0.29, 1e-12);  // tolerance: a few roundings of numbers of order 0.3
  EXPECT_NEAR(oscillating.error, kCalibratedScaleFactorLow * 0.09, 1e-12);
  // Observed order 3 (differences -0.08, -0.01; outside [0.5, 2]): no spread term; scale max(0.01, 0.04,
  // |-0.02 + 0.08|) = 0.06: an anomalously small last step does not shrink the bar.
  const GridConvergence steep = grid_convergence_calibrated(0.39, 0.31, 0.30, kFinePoints, kHighLoad);
  EXPECT_NEAR(steep.order, 3.0, 1e-10);
  EXPECT_NEAR(steep.value, 0.29, 1e-12);
  EXPECT_NEAR(steep.error, kCalibratedScaleFactorHigh * 0.06, 1e-12);
  // Nothing changes, outside the middle band: a zero bar, the grids' honest answer.
  const GridConvergence flat = grid_convergence_calibrated(0.5, 0.5, 0.5, kFinePoints, kHighLoad);
  EXPECT_EQ(flat.error, 0);
  EXPECT_EQ(flat.value, 0.5);
}

TEST(GridConvergence, CalibratedLatticeTermInTheMiddleBandOnly) {
  // Nothing changes between the grids, but 0.01 of 65536 nodes (655 nodes) are in contact: in the middle band
  // the bar is L sqrt(0.01 / 65536) = L 0.01 / sqrt(655.36), the lattice scatter of the count; in the others
  // 0.
  constexpr Real kFinePoints = 65536, kArea = 0.01;
  const Real lattice = std::sqrt(kArea / kFinePoints);
  for (const Real load : {kCalibratedLowLoadLimit, 1e-3, kCalibratedHighLoadLimit}) {  // the limits: middle
    const GridConvergence g = grid_convergence_calibrated(kArea, kArea, kArea, kFinePoints, load);
    EXPECT_NEAR(g.error, kCalibratedLatticeFactorMiddle * lattice, 1e-15) << load;  // tolerance: roundings
    EXPECT_EQ(g.factor, kCalibratedScaleFactorMiddle);
  }
  EXPECT_EQ(grid_convergence_calibrated(kArea, kArea, kArea, kFinePoints, 1e-4).error, 0);
  EXPECT_EQ(grid_convergence_calibrated(kArea, kArea, kArea, kFinePoints, 5e-2).error, 0);
  // No contact: no lattice term (and no division by zero).
  EXPECT_EQ(grid_convergence_calibrated(0, 0, 0, kFinePoints, 1e-3).error, 0);
}

TEST(GridConvergence, CorrectedAreaBarIsTheFactorOnTheCorrection) {
  // Tolerance: a few roundings of numbers of order 0.1.
  EXPECT_NEAR(corrected_area_error(0.12, 0.10), kCalibratedCorrectionFactor * 0.02, 1e-15);
  EXPECT_NEAR(corrected_area_error(0.10, 0.12), kCalibratedCorrectionFactor * 0.02, 1e-15);
  EXPECT_EQ(corrected_area_error(0.3, 0.3), 0);
}

TEST(GridConvergence, TwoGridsAtFormalOrderOneWithFactorThree) {
  const GridConvergence g = grid_convergence_two(0.32, 0.30);
  EXPECT_EQ(g.grids, 2);
  EXPECT_NEAR(g.value, 0.28, 1e-12);  // 2 f(2n) - f(n); tolerance: roundings
  EXPECT_NEAR(g.error, 0.06, 1e-12);
  EXPECT_TRUE(std::isnan(g.order));
}

// The calibration study's three cases whose true error came closest to the bar (results/studies/error_bar/
// table.md, "closest to the bar"), solved again here on the study's grids 64, 128 and 256 (the surface
// generated on 64 points, Fourier-refined; loads solved in the study's order up to the case's), the bar
// checked against the study's truth (the three-grid extrapolation from 256, 512 and 1024 points, too slow
// for a test; copied from results/studies/error_bar/cases.csv with its command:
// PYTHONPATH=build/release/python /usr/bin/python3 scripts/studies/error_bar.py --threads 2 --reuse).
struct HardCase {
  Real hurst, qr_in_q0, qs_in_nyquist, anisotropy;
  std::uint64_t seed;
  Real load;
  Real truth;
};

// The node-count area fractions on the grids 64, 128 and 256.
std::vector<Real> solve_case(const HardCase& c) {
  constexpr Real kLength = 200e-6, kEstar = 1e11;
  constexpr Index kBase = 64;
  const Grid grid{.nx = kBase, .ny = kBase, .lx = kLength, .ly = kLength, .periodic = true};
  const SelfAffinePsd psd{.sigma = 0.5e-6,
                          .hurst = c.hurst,
                          .qr = c.qr_in_q0 * 2 * std::numbers::pi / kLength,
                          .qs = c.qs_in_nyquist * grid.nyquist(),
                          .anisotropy = c.anisotropy};
  const Surface surface = generate_surface(grid, psd, c.seed, 2);
  const std::vector<Real> loads{1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 5e-2};  // the study's
  std::vector<Real> counts;
  for (const Index n : {kBase, 2 * kBase, 4 * kBase}) {
    BemSolverOptions options;
    options.tolerance = 1e-8;  // the study's (the Python BemSolver's default)
    BemSolver solver(n == kBase ? surface : refine(surface, n, n, 2), kEstar, options, 2);
    Real count = 0;
    for (const Real load : loads) {
      if (load > c.load) break;
      const ContactSolution& s = solver.solve(load * kEstar);
      count = static_cast<Real>(s.contact_points) / static_cast<Real>(n * n);
    }
    counts.push_back(count);
  }
  return counts;
}

// gci3's: family, seed, load and truth of the three closest on seeds 101 and 102: H 0.3 seed 102 at 1e-4, H
// 0.7 seed 101 at 3e-4, the narrow band (H 0.5, qr 8 q0, qs half the Nyquist) seed 101 at 1e-4; true error /
// bar 0.28, 0.25, 0.25 in the study.
const HardCase kHardestCases[] = {
    {.hurst = 0.3,
     .qr_in_q0 = 4,
     .qs_in_nyquist = 1,
     .anisotropy = 1,
     .seed = 102,
     .load = 1e-4,
     .truth = 0.0009259905133928571},
    {.hurst = 0.7,
     .qr_in_q0 = 4,
     .qs_in_nyquist = 1,
     .anisotropy = 1,
     .seed = 101,
     .load = 3e-4,
     .truth = 0.005767822265625},
    {.hurst = 0.5,
     .qr_in_q0 = 8,
     .qs_in_nyquist = 0.5,
     .anisotropy = 1,
     .seed = 101,
     .load = 1e-4,
     .truth = 0.001749522650419776},
};

// One test a case (each about 1.5 s of CPU in release).
void expect_covered(const HardCase& c, const GridConvergence& g) {
  // The bar is the claim: no tolerance beyond it.
  EXPECT_LE(std::abs(g.value - c.truth), g.error)
      << "H " << c.hurst << " seed " << c.seed << " load " << c.load << ": value " << g.value << ", truth "
      << c.truth << ", order " << g.order;
}

GridConvergence gci3_of(const std::vector<Real>& counts) {
  return grid_convergence_three(counts[0], counts[1], counts[2]);
}
// The study's finest estimate grid, 256 points a side (the lattice term's node count).
GridConvergence calibrated_of(const std::vector<Real>& counts, Real load) {
  return grid_convergence_calibrated(counts[0], counts[1], counts[2], 256.0 * 256.0, load);
}

TEST(GridConvergence, CoversTheTruthOnTheStudysHardestCaseH03) {
  expect_covered(kHardestCases[0], gci3_of(solve_case(kHardestCases[0])));
}
TEST(GridConvergence, CoversTheTruthOnTheStudysHardestCaseH07) {
  expect_covered(kHardestCases[1], gci3_of(solve_case(kHardestCases[1])));
}
TEST(GridConvergence, CoversTheTruthOnTheStudysHardestCaseNarrowBand) {
  expect_covered(kHardestCases[2], gci3_of(solve_case(kHardestCases[2])));
}

// The calibrated bar's hardest covered cases, one per load band (results/studies/error_bar/table.md,
// "calibrated3 cases closest to the bar", calibration set, seeds 101 to 110): the bar is fitted to cover
// 97.5 % of each band, so the cases above 1 in that table are outside it by design; these are the three
// covered ones closest to it, true error / bar 0.98 (H 0.7 seed 110 at 1e-4), 0.98 (H 0.4 with m2x/m2y = 1/2
// seed 107 at 3e-3) and 0.99 (H 0.9 seed 108 at 5e-2). The truths copied from cases.csv (command above).
const HardCase kCalibratedHardestCases[] = {
    {.hurst = 0.7,
     .qr_in_q0 = 4,
     .qs_in_nyquist = 1,
     .anisotropy = 1,
     .seed = 110,
     .load = 1e-4,
     .truth = 0.0016510009765625},
    {.hurst = 0.4,
     .qr_in_q0 = 4,
     .qs_in_nyquist = 1,
     .anisotropy = 0.5,
     .seed = 107,
     .load = 3e-3,
     .truth = 0.051153432959072036},
    {.hurst = 0.9,
     .qr_in_q0 = 4,
     .qs_in_nyquist = 1,
     .anisotropy = 1,
     .seed = 108,
     .load = 5e-2,
     .truth = 0.7195967131969976},
};

TEST(GridConvergence, CalibratedCoversTheTruthOnTheStudysHardestCaseLowLoad) {
  const HardCase& c = kCalibratedHardestCases[0];
  expect_covered(c, calibrated_of(solve_case(c), c.load));
}
TEST(GridConvergence, CalibratedCoversTheTruthOnTheStudysHardestCaseMiddleLoad) {
  const HardCase& c = kCalibratedHardestCases[1];
  expect_covered(c, calibrated_of(solve_case(c), c.load));
}
TEST(GridConvergence, CalibratedCoversTheTruthOnTheStudysHardestCaseHighLoad) {
  const HardCase& c = kCalibratedHardestCases[2];
  expect_covered(c, calibrated_of(solve_case(c), c.load));
}

}  // namespace
}  // namespace contactbench
