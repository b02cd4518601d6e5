// The moments an isotropic theory reads (docs/theory.md sections 0 and 1: profile, not areal, moments). The
// theories (Greenwood-Williamson with McCool's parameters, Bush-Gibson-Thomas, Persson, the BGT linear law)
// are written for isotropic surfaces with one profile moment of each order: the moments used are the means
// of the x and y profile moments, and a surface whose x and y moments differ by more than kMaxAnisotropy is
// refused rather than silently averaged.
#pragma once

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

}  // namespace contactbench
