// The BEM reference's error bar (bem/grid_convergence.hpp; docs/theory.md section 9.2): Roache's grid
// convergence index on exact power-law sequences, its fallbacks, and on the calibration study's hardest
// cases (scripts/studies/error_bar.py) that its bar covers the study's truth.
#include <gtest/gtest.h>

#include <cmath>

#include "contactbench/bem/grid_convergence.hpp"

namespace contactbench {
namespace {

// f(h) = exact + c h^p on h = 4, 2, 1 (grids n, 2n, 4n).
GridConvergence on_power_law(Real exact, Real c, Real p) {
  return grid_convergence_three(exact + c * std::pow(4.0, p), exact + c * std::pow(2.0, p), exact + c);
}

TEST(GridConvergence, RecoversOrderAndLimitOfAPowerLaw) {
  for (const Real p : {0.6, 1.0, 1.5, 1.9}) {
    const GridConvergence g = on_power_law(0.2, 0.01, p);
    // Tolerance 1e-12: exact arithmetic up to a few roundings of numbers of order 0.2.
    EXPECT_NEAR(g.order, p, 1e-10) << p;
    EXPECT_NEAR(g.value, 0.2, 1e-12) << p;
    EXPECT_EQ(g.factor, kGciFactorThreeGrids);
    EXPECT_EQ(g.grids, 3);
    // In the asymptotic range the fine grid's error is |f3 - f2|/(2^p - 1) = c: the bar is 1.25 of it.
    EXPECT_NEAR(g.error, 1.25 * 0.01, 1e-12) << p;
  }
}

TEST(GridConvergence, UntrustedOrderFallsBackToTheTwoGridFactor) {
  // Oscillating: no order; the formal order 1 and the factor 3 on the larger difference (0.05).
  const GridConvergence oscillating = grid_convergence_three(0.30, 0.25, 0.27);
  EXPECT_TRUE(std::isnan(oscillating.order));
  EXPECT_EQ(oscillating.factor, kGciFactorTwoGrids);
  EXPECT_NEAR(oscillating.error, 3 * 0.05, 1e-12);  // tolerance: a few roundings of 0.05
  EXPECT_NEAR(oscillating.value, 0.29, 1e-12);
  // Observed order 3 (differences 0.08, 0.01): untrusted, order 1 and factor 3 on the larger difference.
  const GridConvergence steep = grid_convergence_three(0.39, 0.31, 0.30);
  EXPECT_NEAR(steep.order, 3.0, 1e-10);
  EXPECT_EQ(steep.factor, kGciFactorTwoGrids);
  EXPECT_NEAR(steep.error, 3 * 0.08, 1e-12);
  EXPECT_NEAR(steep.value, 0.29, 1e-12);
  // A flat last step after a change (a coarse grid's few contact nodes): the bar does not vanish.
  const GridConvergence flat_step = grid_convergence_three(0.0037, 0.0020, 0.0020);
  EXPECT_TRUE(std::isnan(flat_step.order));
  EXPECT_NEAR(flat_step.error, 3 * 0.0017, 1e-15);
  // Nothing changes at all: a zero bar is then the grids' honest answer.
  const GridConvergence flat = grid_convergence_three(0.5, 0.5, 0.5);
  EXPECT_EQ(flat.error, 0);
  EXPECT_EQ(flat.value, 0.5);
}

TEST(GridConvergence, TwoGridsAtFormalOrderOneWithFactorThree) {
  const GridConvergence g = grid_convergence_two(0.32, 0.30);
  EXPECT_EQ(g.grids, 2);
  EXPECT_NEAR(g.value, 0.28, 1e-12);  // 2 f(2n) - f(n); tolerance: roundings
  EXPECT_NEAR(g.error, 0.06, 1e-12);
  EXPECT_TRUE(std::isnan(g.order));
}

}  // namespace
}  // namespace contactbench
