// The Gaussian tail integrals of Greenwood-Williamson theory with a Gaussian summit height density
// (docs/theory.md section 5; Greenwood & Williamson, Proc. R. Soc. A 295, 1966):
//   F_n(t) = (2 pi)^(-1/2) int_t^inf (s - t)^n exp(-s^2/2) ds,   real n >= 0.
//
// Method. With s = t + u, F_n(t) = phi(t) I_n(t), phi(t) = exp(-t^2/2)/sqrt(2 pi) and
//   I_n(t) = int_0^inf u^n exp(-t u - u^2/2) du,
// a positive integrand whose logarithm L(u) = n ln u - t u - u^2/2 is concave with a single maximum u*.
// phi and the maximum exp(L(u*)) are kept as logarithms, the integrand is scaled by exp(-L(u*)), and the
// integral runs over the interval where L(u) > L(u*) - 50 (the rest is below 1e-21 of the integral) with
// tanh-sinh (double-exponential) quadrature, which is exact to round-off for the u^n endpoint singularity at
// u = 0 and needs no tuning to the scale of the integrand (1/t at large t, 1 at negative t). Nothing is
// subtracted, so there is no cancellation, and log F_n is finite even where F_n underflows.
// The closed forms F_0 = erfc(t/sqrt2)/2 (t <= 2) and F_1 = phi(t) - t F_0(t) (t <= 1) are used where they
// are well conditioned; elsewhere (F_1 at large t loses all digits to cancellation) the integral is used.
//
// Accuracy: better than 1e-12 relative over t in [-10, 40] (tested against an independent long double
// quadrature to 1e-9 and docs/theory.md's check values); any finite t and n >= 0 are accepted.
#pragma once

#include "contactbench/core/types.hpp"

namespace contactbench {

// ln F_n(t); finite for every finite t (e.g. about -804.6 at n = 0, t = 40). Throws Error unless n >= 0 and
// both arguments are finite.
Real log_gaussian_tail_integral(Real n, Real t);

// F_n(t) = exp(ln F_n(t)): underflows cleanly to a subnormal or 0 (beyond t of about 38), never NaN.
Real gaussian_tail_integral(Real n, Real t);

}  // namespace contactbench
