// From spectral moments and requested loads to a LoadAreaCurve: what the moment theories
// (Greenwood-Williamson with McCool's parameters, Persson, the BGT linear law) share.
//
// - The theories are written for isotropic surfaces with one profile moment of each order. The moments used
// are
//   the means of the x and y profile moments (docs/theory.md sections 0 and 1: profile, not areal, moments),
//   and a surface whose x and y moments differ by more than kMaxAnisotropy is refused rather than silently
//   averaged.
// - Requested loads P/(E* A0) must be finite, positive and ascending.
// - A theory whose load is a monotone function of a separation is solved for the separation that gives each
//   requested load with Brent's bracketed root finder (find_root).
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>

#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// Largest accepted |m2x/m2y - 1| and |m4x/m4y - 1|.
inline constexpr Real kMaxAnisotropy = 0.05;

// Isotropic profile moments: m0 [m^2], m2 = (m2x + m2y)/2 [-], m4 = (m4x + m4y)/2 [m^-2].
struct IsotropicMoments {
  Real m0 = 0;
  Real m2 = 0;
  Real m4 = 0;
};

// All three moments, refusing (Error naming `method`, the x and y values and their ratio) a surface whose
// m2x/m2y or m4x/m4y differs from 1 by more than kMaxAnisotropy, and non-finite or non-positive moments.
IsotropicMoments isotropic_moments(const SpectralMoments& moments, std::string_view method);

// Only m2 = (m2x + m2y)/2, for theories that use nothing else: checks only m2x, m2y.
Real isotropic_m2(const SpectralMoments& moments, std::string_view method);

// "profile moments, means of x and y: m0 = ... m^2, m2 = ..., m4 = ... 1/m^2, alpha = m0 m4/m2^2 = ...".
std::string describe(const IsotropicMoments& moments);

// Refuses (Error naming `method`, the value and its position) a load that is not finite and > 0 or that is
// below its predecessor.
void validate_loads(std::span<const Real> loads, std::string_view method);

// A number in the form the parameters strings use (%.6g).
std::string format_number(Real value);

// Brent's method (R. P. Brent, Algorithms for Minimization without Derivatives, 1973, ch. 4; the netlib
// zeroin): a root of f in the bracket [a, b], where fa = f(a) and fb = f(b) have opposite signs (or one is
// 0). Returns when |f| <= f_tolerance or the bracket is narrower than 4 eps |x| + x_tolerance.
Real find_root(const std::function<Real(Real)>& f, Real a, Real b, Real fa, Real fb, Real f_tolerance,
               Real x_tolerance);

}  // namespace contactbench
