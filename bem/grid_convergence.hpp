// The BEM reference's error bar from a grid sequence (docs/theory.md section 9.2): Roache's grid convergence
// index (GCI; Roache, Verification and Validation in Computational Science and Engineering, 1998, ch. 5;
// adopted by ASME V&V 20-2009, section 2-4), on grids refined by a ratio of 2.
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

struct GridConvergence {
  Real value = 0;   // the finest grid's value extrapolated at the order used
  Real error = 0;   // the error bar (GCI) on value: |value - exact| <= error, as calibrated
  Real order = 0;   // observed (not clamped); NaN with two grids, or without monotone convergence
  Real factor = 0;  // the factor of safety applied
  int grids = 0;    // 2 or 3
};

// Three values of the same quantity on grids of n, 2n and 4n points a side (coarse, medium, fine), converging
// monotonically: the observed order p = log2((medium - coarse)/(fine - medium)), the order used q = p clamped
// to [0.5, 1] (never above the formal order 1), value = fine + (fine - medium)/(2^q - 1), error = F |fine -
// medium|/(2^q - 1) with F = 1.25 when |p - 1| <= 0.1, else 3. Not monotone, or p > 2: value = 2 fine -
// medium, error = 3 max(|medium - coarse|, |fine - medium|) (Eca & Hoekstra, J. Comput. Phys. 262, 2014).
// docs/theory.md 9.2.
GridConvergence grid_convergence_three(Real coarse, Real medium, Real fine);

// Two values on n and 2n points a side at the formal order 1: value = 2 fine - medium, error = 3 |fine -
// medium|.
GridConvergence grid_convergence_two(Real medium, Real fine);

}  // namespace contactbench
