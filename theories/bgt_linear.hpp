// The BGT linear law: the small-load limit of the Bush-Gibson-Thomas model (A. W. Bush, R. D. Gibson and
// T. R. Thomas, Wear 35, 87, 1975; docs/theory.md section 5), under its own name, never "BGT":
//   A/A0 = sqrt(pi) P/(E* A0 sqrt(m2)) = sqrt(2 pi) p/(E* gbar)   (areal kappa sqrt(2 pi) = 2.507),
// with m2 the isotropic profile moment (mean of m2x and m2y; anisotropy above 5 % refused,
// isotropic_moments.hpp) and gbar = sqrt(2 m2). At realistic loads the full BGT model lies about a factor two
// below this law. The law is linear without bound; curves cap A/A0 at 1 and say so.
#pragma once

#include <span>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// A/A0 = sqrt(pi) load / sqrt(m2), load = P/(E* A0); not capped.
Real bgt_linear_area_fraction(Real load, Real m2);

// The load at which the law reaches A/A0 = 1: sqrt(m2/pi).
Real bgt_linear_full_contact_load(Real m2);

// The curve at the requested loads (finite, > 0, ascending): method "bgt_linear", A/A0 capped at 1 (the
// parameters then say "capped at A/A0 = 1 for loads >= X"), separation and spots NaN.
LoadAreaCurve bgt_linear_curve(const SpectralMoments& moments, std::span<const Real> loads);

}  // namespace contactbench
