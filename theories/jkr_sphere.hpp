// One adhesive sphere in the JKR limit (K. L. Johnson, K. Kendall, A. D. Roberts, Proc. R. Soc. A 324, 301,
// 1971; Johnson, Contact Mechanics, 1985, section 5.5): a paraboloid of radius R on a half-space of contact
// modulus E* (K = 4E*/3) with a work of adhesion w and an attraction of vanishing range. It needs only w.
// In the dimensionless variables of Johnson and Greenwood (J. Colloid Interface Sci. 192, 326, 1997), the
// same as theories/maugis_dugdale_sphere.hpp (ā = a (K/(π w R²))^(1/3), P̄ = P/(π w R),
// δ̄ = δ (K²/(π² w² R))^(1/3)):
//   P̄ = ā³ − √(6 ā³),   δ̄ = ā² − √(8 ā/3),   dδ̄/dā = 2ā − √(2/(3 ā)),
// the λ → ∞ limit of Maugis' equations. Under load control the pull-off is P̄ = −1.5 (1.5 π w R) at
// ā = (3/2)^(1/3); under approach control the branch in contact is stable while dδ̄/dā > 0, that is for
// ā > 6^(−1/3), and a summit pulled beyond δ̄ = 6^(−2/3) − √(8/3) 6^(−1/6) ≈ −0.9086 jumps out of contact.
#pragma once

#include "contactbench/core/types.hpp"

namespace contactbench {

struct JkrState {
  Real load = 0;            // P̄
  Real approach = 0;        // δ̄
  Real approach_slope = 0;  // dδ̄/dā
};

// The state at a dimensionless contact radius ā > 0 (Error otherwise).
JkrState jkr_at_radius(Real contact_radius);

// ā at which δ̄ = 0: a summit that just touches the flat, on the branch in contact: (8/3)^(1/3).
Real jkr_radius_at_touch();

// ā at which dδ̄/dā = 0, where a retracting summit jumps out of contact: 6^(−1/3).
Real jkr_radius_at_separation();

}  // namespace contactbench
