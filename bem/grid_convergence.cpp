#include "contactbench/bem/grid_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contactbench {

GridConvergence grid_convergence_three(Real coarse, Real medium, Real fine) {
  const Real d21 = medium - coarse, d32 = fine - medium;
  GridConvergence g;
  g.grids = 3;
  g.order = d21 * d32 > 0 ? std::log2(d21 / d32) : std::numeric_limits<Real>::quiet_NaN();
  if (!(d21 * d32 > 0) || g.order > kLargestTrustedOrder) {
    // No monotone convergence (oscillation, or a flat step, as a coarse grid's few contact nodes give), or an
    // order far above the formal one (a last step anomalously small; calibration study: observed 5.8 and a
    // true error 3.6 times the bar it would give): the formal order, and the two-grid factor on the largest
    // difference of the three (Eca and Hoekstra 2014's rule for anomalous convergence), so that a step that
    // happens to be small does not make the bar vanish.
    g.factor = kGciFactorTwoGrids;
    const Real denominator = std::exp2(kFormalAreaOrder) - 1;
    g.value = fine + d32 / denominator;
    g.error = g.factor * std::max(std::abs(d21), std::abs(d32)) / denominator;
    return g;
  }
  // Roache's GCI as Oberkampf and Roy apply it (2010, section 8.7): the order used is the observed one, at
  // least 0.5 and at most the formal order (coarse grids show a higher apparent order that the finer ones do
  // not keep: scripts/studies/error_bar.py, gci3_roache); the factor 1.25 only when the observed order is
  // within 10 % of the formal one, else 3.
  const Real used = std::clamp(g.order, kSmallestTrustedOrder, kFormalAreaOrder);
  g.factor = std::abs(g.order - kFormalAreaOrder) <= kOrderAgreement * kFormalAreaOrder ? kGciFactorThreeGrids
                                                                                        : kGciFactorTwoGrids;
  const Real denominator = std::exp2(used) - 1;
  g.value = fine + d32 / denominator;
  g.error = g.factor * std::abs(d32) / denominator;
  return g;
}

GridConvergence grid_convergence_calibrated(Real coarse, Real medium, Real fine, Real fine_points,
                                            Real load) {
  const Real d21 = medium - coarse, d32 = fine - medium;
  GridConvergence g;
  g.grids = 3;
  g.order = d21 * d32 > 0 ? std::log2(d21 / d32) : std::numeric_limits<Real>::quiet_NaN();
  // The band's factors (calibrated per band: the extrapolate's error relative to the grids' changes differs
  // between a few spots of a few pixels at small loads and many larger ones at high loads).
  const bool low = load<kCalibratedLowLoadLimit, high = load> kCalibratedHighLoadLimit;
  g.factor = low    ? kCalibratedScaleFactorLow
             : high ? kCalibratedScaleFactorHigh
                    : kCalibratedScaleFactorMiddle;
  const Real lattice_factor = low || high ? 0 : kCalibratedLatticeFactorMiddle;
  // The formal order 1 (section 9.1): the coarse grids' apparent order is not kept by finer ones, and the
  // order-1 extrapolate was the more accurate in the calibration study (docs/studies.md section 7).
  g.value = 2 * fine - medium;
  // The scale of the extrapolate's error: the last step, the step before as the order 1 carries it to the
  // last (so that an anomalously small last step does not shrink the bar), and how much the order-1
  // extrapolate itself moved between the two pairs (how far the grids are from the asymptotic range).
  const Real scale = std::max({std::abs(d32), std::abs(d21) / 2, std::abs(2 * d32 - d21)});
  // The lattice scatter of the finest grid's count, fine / sqrt(N) with N = fine x fine_points nodes in
  // contact: what three grids do not see converge when the spots are a few pixels.
  const Real lattice = fine > 0 && fine_points > 0 ? std::sqrt(fine / fine_points) : 0;
  g.error = std::max(g.factor * scale, lattice_factor * lattice);
  // The spread over plausible orders: the extrapolate at the observed one, when that is trusted.
  if (g.order >= kSmallestTrustedOrder && g.order <= kLargestTrustedOrder)
    g.error = std::max(g.error, std::abs(fine + d32 / (std::exp2(g.order) - 1) - g.value));
  return g;
}

Real corrected_area_error(Real nodes, Real corrected) {
  return kCalibratedCorrectionFactor * std::abs(nodes - corrected);
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
