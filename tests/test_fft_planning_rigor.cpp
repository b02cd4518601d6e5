// The planner level chosen by the work (core/fft.hpp choose_fft_rigor, bem/convolution.hpp; docs/solvers.md,
// Planning): small lattices and coarse levels estimated, a measured plan taken from the wisdom whenever it is
// there (FFTW_WISDOM_ONLY), measured otherwise only when the wisdom is kept or the run's expected
// applications pay it back; and a solve's answer does not depend on which (beyond FFTW's round-off).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/convolution.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/fftw_wisdom.hpp"
#include "contactbench/core/generation.hpp"

namespace contactbench {
namespace {

// Each test starts with no wisdom and the planner told nothing of the work, and leaves it so.
class PlanningRigor : public ::testing::Test {
 protected:
  PlanningRigor() { reset(); }
  ~PlanningRigor() override { reset(); }
  static void reset() {
    forget_fftw_wisdom();
    set_fft_work({});
  }
};

// A circular convolution of a fixed input on an n x n lattice, planned at `rigor`.
struct Convolved {
  FftRigor planned;
  std::vector<double> out;
};
Convolved convolve(Index n, FftRigor rigor) {
  Convolution<double> convolution(n, n, false, 1, rigor);
  Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> multiplier(n, n / 2 + 1);
  for (Index ky = 0; ky < n; ++ky)
    for (Index kx = 0; kx <= n / 2; ++kx)
      multiplier(ky, kx) = 1.0 / (1.0 + static_cast<double>(std::min(ky, n - ky) + kx));  // even in ky
  convolution.set_multiplier(multiplier);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<double> in(static_cast<std::size_t>(n * n)), out(in.size());
  for (double& v : in)
    v = uniform(random);
  convolution.apply(in.data(), out.data());
  return {convolution.planned_rigor(), out};
}

TEST_F(PlanningRigor, TheRuleChoosesByLatticeWisdomAndWork) {
  constexpr Index small = 256 * 256, large = kMinPointsForMeasuredPlans;
  // Nothing known of the work: estimate; explicit levels are kept as asked.
  EXPECT_EQ(choose_fft_rigor(FftRigor::by_work, large), FftRigor::estimate);
  EXPECT_EQ(choose_fft_rigor(FftRigor::measure, small), FftRigor::measure);
  EXPECT_EQ(choose_fft_rigor(FftRigor::estimate, large), FftRigor::estimate);
  // Wisdom kept: the large lattice is measured (paid once per machine), the small one never.
  set_fft_work({.wisdom_kept = true});
  EXPECT_EQ(choose_fft_rigor(FftRigor::by_work, large), FftRigor::measure);
  EXPECT_EQ(choose_fft_rigor(FftRigor::by_work, small), FftRigor::estimate);
  // No file, but enough applications to pay back within the run; just below the count, not.
  set_fft_work({.wisdom_kept = false, .expected_applications = kPayBackApplications + 1});
  EXPECT_EQ(choose_fft_rigor(FftRigor::by_work, large), FftRigor::measure);
  EXPECT_EQ(choose_fft_rigor(FftRigor::by_work, small), FftRigor::estimate);
  set_fft_work({.wisdom_kept = false, .expected_applications = kPayBackApplications});
  EXPECT_EQ(choose_fft_rigor(FftRigor::by_work, large), FftRigor::estimate);
}

TEST_F(PlanningRigor, AWisdomOnlyLookupFallsBackAndThenFindsTheMeasuredPlans) {
  constexpr Index n = 512;  // the smallest lattice the rule measures
  static_assert(n * n == kMinPointsForMeasuredPlans);
  // No wisdom, nothing kept: the wisdom-only lookup makes no plan and the rule estimates.
  const Convolved estimated = convolve(n, FftRigor::by_work);
  EXPECT_EQ(estimated.planned, FftRigor::estimate);
  // Measured once (its wisdom now held), a later convolution by the work takes the measured plans without
  // measuring: the same plans, so the same result to the last bit (tolerance zero).
  const Convolved measured = convolve(n, FftRigor::measure);
  EXPECT_EQ(measured.planned, FftRigor::measure);
  const Convolved from_wisdom = convolve(n, FftRigor::by_work);
  EXPECT_EQ(from_wisdom.planned, FftRigor::measure);
  EXPECT_EQ(std::memcmp(measured.out.data(), from_wisdom.out.data(), measured.out.size() * sizeof(double)),
            0);
  // Estimated and measured plans differ only by FFTW's round-off: a few ulps of the largest value per
  // transform pair (the sums are ordered differently); 1e-13 of the largest value leaves room for the
  // ~log2(512) = 9 butterfly levels of each of the four 1D passes, well above what differing plans give.
  const double largest =
      std::abs(*std::max_element(measured.out.begin(), measured.out.end(),
                                 [](double a, double b) { return std::abs(a) < std::abs(b); }));
  for (std::size_t k = 0; k < measured.out.size(); ++k)
    ASSERT_NEAR(estimated.out[k], measured.out[k], 1e-13 * largest) << "at " << k;
  // Below the rule's lattice, by the work is estimated even with the wisdom kept.
  set_fft_work({.wisdom_kept = true});
  EXPECT_EQ(convolve(256, FftRigor::by_work).planned, FftRigor::estimate);
}

// A 256 x 256 non-periodic solve (its operator's lattice is 512^2 padded: the finest level the rule may
// measure; its coarse levels are estimated either way) with estimated plans and with measured ones.
ContactSolution solve_with(const FftWork& work) {
  forget_fftw_wisdom();
  set_fft_work(work);
  const Grid grid{.nx = 256, .ny = 256, .lx = 100e-6, .ly = 100e-6, .periodic = false};
  const Surface surface = generate_surface(
      grid,
      SelfAffinePsd{.sigma = 0.5e-6, .hurst = 0.7, .qr = 2 * 3.14e4, .qs = std::nullopt, .anisotropy = 1}, 5,
      1);
  BemSolverOptions options;
  options.coarse_start = true;
  BemSolver solver(surface, 1e11 / (1 - 0.09), options, 1);
  return solver.solve(0.01 * 1e11 / (1 - 0.09));
}

TEST_F(PlanningRigor, ASolveWithEstimatedPlansEqualsOneWithMeasuredPlans) {
  const ContactSolution estimated = solve_with({});
  const ContactSolution measured = solve_with({.wisdom_kept = true});
  ASSERT_TRUE(estimated.converged && measured.converged);
  // Relative 1e-12 on the pressures (against the largest) and the separation: the plans change only the
  // round-off of each transform (~1e-16 relative), which the solve carries but does not amplify past its
  // own tolerance-free fixed point; 1e-12 leaves four orders of room and is far below the solve's
  // tolerance of 1e-10, so an answer that moved with the plans would fail.
  const double largest = measured.pressure.abs().maxCoeff();
  EXPECT_LE((estimated.pressure - measured.pressure).abs().maxCoeff(), 1e-12 * largest);
  EXPECT_NEAR(estimated.separation, measured.separation, 1e-12 * std::abs(measured.separation));
  // The contact area: the same nodes in contact.
  EXPECT_EQ((estimated.pressure > 0).count(), (measured.pressure > 0).count());
}

}  // namespace
}  // namespace contactbench
