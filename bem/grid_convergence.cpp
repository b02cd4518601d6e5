#include "contactbench/bem/grid_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contactbench {

GridConvergence grid_convergence_three(Real coarse, Real medium, Real fine) {
  const Real d21 = medium - coarse, d32 = fine - medium;
  GridConvergence g;
  g.grids = 3;
  // Monotone convergence (both differences of one sign) defines an order; otherwise none is observed.
  g.order = d21 * d32 > 0 ? std::log2(d21 / d32) : std::numeric_limits<Real>::quiet_NaN();
  if (std::isfinite(g.order) && g.order >= kSmallestTrustedOrder && g.order <= kLargestTrustedOrder) {
    const Real denominator = std::exp2(g.order) - 1;
    g.factor = kGciFactorThreeGrids;
    g.value = fine + d32 / denominator;
    g.error = g.factor * std::abs(d32) / denominator;
    return g;
  }
  // No order to trust (oscillation, a flat step, or a grid outside the asymptotic range): the formal order,
  // and the two-grid factor on the largest difference of the three (Eca and Hoekstra 2014's rule for
  // anomalous convergence), so that a step that happens to be flat does not make the bar vanish.
  const Real denominator = std::exp2(kFormalAreaOrder) - 1;
  g.factor = kGciFactorTwoGrids;
  g.value = fine + d32 / denominator;
  g.error = g.factor * std::max(std::abs(d21), std::abs(d32)) / denominator;
  return g;
}

GridConvergence grid_convergence_two(Real medium, Real fine) {
  GridConvergence g;
  g.grids = 2;
  g.order = std::numeric_limits<Real>::quiet_NaN();
  g.factor = kGciFactorTwoGrids;
  const Real denominator = std::exp2(kFormalAreaOrder) - 1;
  g.value = fine + (fine - medium) / denominator;
  g.error = g.factor * std::abs(fine - medium) / denominator;
  return g;
}

}  // namespace contactbench
