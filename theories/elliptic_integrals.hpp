// Complete elliptic integrals through Carlson's symmetric integrals (B. C. Carlson, "Numerical computation of
// real or complex elliptic integrals", Numer. Algorithms 10, 13, 1995; DLMF 19.16, 19.25, 19.36).
//
//   R_F(x, y, z) = (1/2) int_0^inf dt / sqrt((t + x)(t + y)(t + z))
//   R_D(x, y, z) = (3/2) int_0^inf dt / ((t + z) sqrt((t + x)(t + y)(t + z)))
//
// computed with Carlson's duplication algorithm to full double precision (relative error a few ulps). With
// the parameter m = e^2 (e the modulus) and y = 1 - m (DLMF 19.25.1):
//   K(m) = R_F(0, 1 - m, 1),   K(m) - E(m) = (m/3) R_D(0, 1 - m, 1),   E(m)/(1 - m) - K(m) = (m/3) R_D(0, 1,
//   1 - m),
// so the combinations (K - E)/m and (E/(1 - m) - K)/m that elliptic Hertz contact needs are evaluated without
// cancellation as m -> 0, and stay finite and accurate as m -> 1 (K grows like ln(4/sqrt(1 - m))).
#pragma once

#include "contactbench/core/types.hpp"

namespace contactbench {

// R_F(x, y, z): x, y, z >= 0 and finite, at most one of them 0; throws Error otherwise.
Real carlson_rf(Real x, Real y, Real z);

// R_D(x, y, z): x, y >= 0 and finite, at most one of them 0, z > 0 and finite; throws Error otherwise.
Real carlson_rd(Real x, Real y, Real z);

// K(m) = int_0^(pi/2) (1 - m sin^2 t)^(-1/2) dt for the parameter m in [0, 1]; +infinity at m = 1.
Real elliptic_k(Real m);

// E(m) = int_0^(pi/2) (1 - m sin^2 t)^(1/2) dt for m in [0, 1]; E(1) = 1.
Real elliptic_e(Real m);

// (K(m) - E(m))/m = R_D(0, 1 - m, 1)/3 for m in [0, 1): pi/4 at m = 0, no cancellation.
Real elliptic_k_minus_e_over_m(Real m);

}  // namespace contactbench
