// The multi-plateaus contact model of G. F. Wang, X. M. Liang and D. Yan (docs/theory.md section 4).
//
// At separation z the contact is N(z) flat-ended cylinders of radius R = sqrt(A_c/(pi N)) (eq. 1); lowering
// the flat by dz adds dP = 2 E* R N dz by Sneddon's solution (eq. 2), so (eq. 3)
//   P(z) = (2 E* / sqrt(pi)) int_z^hmax sqrt(A_c(s) N(s)) ds,   real contact area = A_c(z).
// The model ignores interaction between spots and takes the bearing area as the real area.
#pragma once

#include <span>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/sweep.hpp"

namespace contactbench {

// The load-area curve of a sweep. Between two successive levels z[j] > z[j+1] the set {h > s} for s in
// [z[j+1], z[j]) is the set reported at z[j+1]: the sum over levels uses that value. For exact levels (every
// distinct height) A_c N is constant there and the sum is the integral exactly; for the paper's or uniform
// levels it is the right-endpoint Riemann sum with the level step. Loads are P/(E* A0), so E* drops out.
LoadAreaCurve plateau_model(const SweepCurve& sweep);

// The model's curve (model = plateau_model(sweep)) at requested loads P/(E* A0) (finite, > 0, ascending),
// exactly, without interpolation error: P(z) is linear in z between two levels and the contact set there is
// the one of the lower level (see above), so a load in (P[j-1], P[j]] has the area and spots of level j and a
// separation linear between z[j-1] and z[j]. Below the lowest height every point touches: one spot of area
// A0, dP = 2 E* sqrt(A0/pi) dz, so loads beyond the last level of an exact or uniform sweep (which ends at
// the lowest height) get A/A0 = 1. The paper's levels stop at the mean plane: loads beyond get NaN, and the
// parameters say from which load.
LoadAreaCurve plateau_curve_at_loads(const SweepCurve& sweep, const LoadAreaCurve& model,
                                     std::span<const Real> loads);

}  // namespace contactbench
