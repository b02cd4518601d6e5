// One adhesive sphere: Maugis' solution (D. Maugis, J. Colloid Interface Sci. 150, 243, 1992) of a paraboloid
// of radius R on an elastic half-space of contact modulus E* with a Dugdale attraction σ0 over a gap δc =
// w/σ0 (docs/theory.md section 10), in the dimensionless form of Johnson and Greenwood (J. Colloid Interface
// Sci. 192, 326, 1997) with K = 4E*/3:
//   ā = a (K/(π w R^2))^(1/3),  P̄ = P/(π w R),  δ̄ = δ (K^2/(π^2 w^2 R))^(1/3),  λ = 2σ0 (R/(π w K^2))^(1/3),
// m = c/a the outer radius of the attractive annulus over the contact radius, fixed by
//   (λā²/2)[√(m²−1) + (m²−2) atan√(m²−1)] + (4λ²ā/3)[√(m²−1) atan√(m²−1) − m + 1] = 1,
//   P̄ = ā³ − λā²[√(m²−1) + m² atan√(m²−1)],   δ̄ = ā² − (4/3)λā√(m²−1).
// It spans DMT (λ → 0, pull-off 2πRw) and JKR (λ → ∞, pull-off 1.5πRw). The single asperity of the adhesive
// asperity theories and the analytic check of the adhesive BEM.
#pragma once

#include "contactbench/core/types.hpp"

namespace contactbench {

struct MaugisDugdaleState {
  Real radius_ratio = 1;  // m = c/a
  Real load = 0;          // P̄
  Real approach = 0;      // δ̄
};

// The state at a dimensionless contact radius ā > 0 for Maugis' parameter λ > 0.
MaugisDugdaleState maugis_dugdale_at_radius(Real contact_radius, Real lambda);

// The dimensionless contact radius at a dimensionless approach δ̄ on the branch in contact that a falling or
// rising flat follows while ā exceeds the radius where dδ̄/dā = 0 (the jump out of contact under
// separation control); NaN when δ̄ lies below that branch.
Real maugis_dugdale_radius_at_approach(Real approach, Real lambda);

// The dimensionless contact radius at a dimensionless load P̄ on the branch stable under load control (ā above
// the radius of the smallest load); NaN below the pull-off load.
Real maugis_dugdale_radius_at_load(Real load, Real lambda);

// The pull-off load under load control: the smallest P̄ of the branch in contact (≤ 0; -2 for λ → 0, -1.5
// for λ → ∞), and the ā where it is reached.
struct MaugisDugdalePullOff {
  Real load = 0;
  Real contact_radius = 0;
};
MaugisDugdalePullOff maugis_dugdale_pull_off(Real lambda);

// The scales of the dimensionless variables for R [m], E* [Pa] and w [J/m^2]: a = ā * radius_scale, and so
// on.
struct MaugisDugdaleScales {
  Real radius = 0;    // (π w R^2 / K)^(1/3) [m]
  Real load = 0;      // π w R [N]
  Real approach = 0;  // (π^2 w^2 R / K^2)^(1/3) [m]
};
MaugisDugdaleScales maugis_dugdale_scales(Real sphere_radius, Real modulus, Real work);

}  // namespace contactbench
