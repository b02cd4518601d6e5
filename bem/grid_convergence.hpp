// The BEM reference's error bar from a grid sequence (docs/theory.md section 9.2), on grids refined by a
// ratio of 2: Roache's grid convergence index (GCI; Roache, Verification and Validation in Computational
// Science and Engineering, 1998, ch. 5; adopted by ASME V&V 20-2009, section 2-4), and the bar calibrated on
// the BEM's own grid sequences (scripts/studies/error_bar.py) for the order-1 extrapolate, and for the
// perimeter-corrected area of one grid.
#pragma once

#include "contactbench/core/types.hpp"

namespace contactbench {

// Roache's factors of safety: 1.25 with three grids and an observed order, 3 with two grids (order assumed).
inline constexpr Real kGciFactorThreeGrids = 1.25;
inline constexpr Real kGciFactorTwoGrids = 3.0;
// The least order used (a smaller observed one is taken as 0.5, a wider bar), and how close the observed
// order must be to the formal one for the three-grid factor (Oberkampf & Roy, Verification and Validation in
// Scientific Computing, 2010, section 8.7: 10 %).
inline constexpr Real kSmallestTrustedOrder = 0.5;
inline constexpr Real kOrderAgreement = 0.1;
// Above this observed order the grids are taken as outside the asymptotic range (twice the formal order).
inline constexpr Real kLargestTrustedOrder = 2.0;
// The formal order of the node-count area in the pixel size (docs/theory.md section 9.1).
inline constexpr Real kFormalAreaOrder = 1.0;

// The calibrated bars' factors (docs/theory.md section 9.2), fitted on the calibration set of
// scripts/studies/error_bar_candidates.py (results/studies/error_bar/raw.csv, holdout.csv, more.csv: 76
// surfaces, seeds 101 to 110, 6 loads, grids 64/128/256 against a truth from 256/512/1024; 456 cases), then
// checked once on a fresh hold-out (fresh.csv, seeds 111 to 120; docs/studies.md section 7).
// Node count, three grids (error_estimate = "calibrated3"): per load band, the factors with which the bar
// covered 97.5 % of the band's calibration cases (the least median bar / true error over the lattice factor),
// rounded up to two digits. Bands: P/(E* A0) below kCalibratedLowLoadLimit, up to kCalibratedHighLoadLimit,
// above (the geometric means between the study's loads 3e-4 and 1e-3, 3e-3 and 1e-2).
inline constexpr Real kCalibratedLowLoadLimit = 5.5e-4;
inline constexpr Real kCalibratedHighLoadLimit = 5.5e-3;
inline constexpr Real kCalibratedScaleFactorLow = 0.59;     // fitted 0.5875
inline constexpr Real kCalibratedScaleFactorMiddle = 0.27;  // fitted 0.2648
inline constexpr Real kCalibratedScaleFactorHigh = 0.18;    // fitted 0.1735
// The lattice term's factor (fitted 1.26 in the middle band; 0 in the others, where it did not narrow the
// bar).
inline constexpr Real kCalibratedLatticeFactorMiddle = 1.3;
// Perimeter-corrected area of one grid, on the size of its correction |N - A_corrected|: the largest ratio
// over the grids 64, 128 and 256 was 0.702; out of sample it covered all 288 cases (96 on each grid).
inline constexpr Real kCalibratedCorrectionFactor = 0.71;

struct GridConvergence {
  Real value = 0;   // the extrapolated value (at the order used)
  Real error = 0;   // the error bar on value: |value - exact| <= error, as calibrated
  Real order = 0;   // observed (not clamped); NaN with two grids, or without monotone convergence
  Real factor = 0;  // the factor of safety (gci) or the calibrated factor applied
  int grids = 0;    // 2 or 3
};

// Three values of the same quantity on grids of n, 2n and 4n points a side (coarse, medium, fine), converging
// monotonically: the observed order p = log2((medium - coarse)/(fine - medium)), the order used q = p clamped
// to [0.5, 1] (never above the formal order 1), value = fine + (fine - medium)/(2^q - 1), error = F |fine -
// medium|/(2^q - 1) with F = 1.25 when |p - 1| <= 0.1, else 3. Not monotone, or p > 2: value = 2 fine -
// medium, error = 3 max(|medium - coarse|, |fine - medium|) (Eca & Hoekstra, J. Comput. Phys. 262, 2014).
// docs/theory.md 9.2.
GridConvergence grid_convergence_three(Real coarse, Real medium, Real fine);

// The calibrated three-grid bar on the order-1 extrapolate (docs/theory.md section 9.2): value = 2 fine -
// medium, error = max(K s, L sqrt(fine / fine_points), |E_p - value|) with the scale s = max(|fine - medium|,
// |medium - coarse|/2, |(2 fine - medium) - (2 medium - coarse)|) (the last step, the step before at order 1,
// the change of the order-1 extrapolate), sqrt(fine / fine_points) = fine / sqrt(N) the lattice scatter of
// the N = fine x fine_points contact nodes of the finest grid, K and L the factors of the load band of
// `load` = P/(E* A0) (above), and E_p = fine + (fine - medium)/(2^p - 1) the extrapolate at the observed
// order p when the counts converge monotonically with p in [0.5, 2] (else no such term): an exact power law
// of such an order is always covered. fine_points: the finest grid's nodes (nx ny).
GridConvergence grid_convergence_calibrated(Real coarse, Real medium, Real fine, Real fine_points, Real load);

// The calibrated bar on one grid's perimeter-corrected area (docs/theory.md section 9.2):
// kCalibratedCorrectionFactor |nodes - corrected|, the correction's own size.
Real corrected_area_error(Real nodes, Real corrected);

// Two values on n and 2n points a side at the formal order 1: value = 2 fine - medium, error = 3 |fine -
// medium|.
GridConvergence grid_convergence_two(Real medium, Real fine);

}  // namespace contactbench
