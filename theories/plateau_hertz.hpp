// The Hertz-consistent plateau model: the project's own variant of the multi-plateaus model, NOT the paper's
// (docs/theory.md section 8). Same cut, same spots, same Sneddon stiffness per spot, but each plateau's
// contact radius is the one an elastic paraboloid with that bearing radius has, a = r_b / sqrt(2), instead of
// the bearing radius r_b itself. Then (section 8.3)
//   P_H(z) = P(z) / sqrt(2),   A_H(z) = A_c(z) / 2,
// with P(z), A_c(z) the paper's model (theories/plateau_model.hpp). It is exact for a paraboloid (Hertz) and
// 1.11 x the exact area at equal load for a cone (the paper's model: 2^(2/3) = 1.59 and pi/2 = 1.57).
#pragma once

#include <span>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/sweep.hpp"

namespace contactbench {

// The variant's curve at every level of the sweep, from the paper's model on the same sweep
// (paper_model = plateau_model(sweep)).
LoadAreaCurve plateau_hertz(const LoadAreaCurve& paper_model);

// The variant at requested loads P/(E* A0) (finite, > 0, ascending): the paper's model at sqrt(2) x each load
// (plateau_curve_at_loads, exact between levels), its area halved. Where the paper's model reaches full
// contact the paraboloid correspondence means nothing (every point of the surface touches, yet the variant
// would say half): those loads get NaN, and the parameters say from which load.
LoadAreaCurve plateau_hertz_curve_at_loads(const SweepCurve& sweep, const LoadAreaCurve& paper_model,
                                           std::span<const Real> loads);

// The variant's contact stiffness per unit area over E*, K_H/E* = -d(P_H/(E* A0))/dz [1/m] (docs/theory.md
// section 12.5): N spots of contact radius a = sqrt(A_H/(pi N)), each a flat punch of stiffness 2 E* a, so
//   K_H = 2 E* sqrt(A_H N / pi) / A0 = K / sqrt(2),
// K the paper's model's at the same level (its area A_c = 2 A_H). area_fraction = A_H/A0, spots = N at the
// load (a curve's row); NaN in gives NaN out.
Real plateau_hertz_stiffness(Real area_fraction, Real spots, Real nominal_area);

}  // namespace contactbench
