// Persson's contact theory at full magnification (B. N. J. Persson, J. Chem. Phys. 115, 3840, 2001;
// docs/theory.md section 5): A/A0 = erf(p / (2 sqrt(G))), G = (pi/4) E*^2 int q^3 C(q) dq, with p = P/A0 the
// nominal pressure.
//
// For an isotropic continuum the profile moment is m2 = pi int q^3 C dq (docs/theory.md section 1), so
// G = (E*^2/4) m2 and the same law reads A/A0 = erf(p/(E* sqrt(m2))) = erf(sqrt2 p/(E* gbar)), gbar = sqrt(2
// m2) the areal rms gradient. Small loads: A/A0 = sqrt(8/pi) p/(E* gbar) (areal kappa sqrt(8/pi) = 1.596).
// Both written forms are given; loads are dimensionless, load = P/(E* A0) = p/E*, so E* drops out.
//
// Moments: the isotropic m2 is the mean of the x and y profile moments, (m2x + m2y)/2 = <|grad h|^2>/2; a
// surface whose m2x/m2y differs from 1 by more than 5 % is refused (isotropic_moments.hpp).
#pragma once

#include <span>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// The moment form: A/A0 = erf(load / sqrt(m2)), load = P/(E* A0), m2 the isotropic profile moment.
Real persson_area_fraction(Real load, Real m2);

// The PSD form: A/A0 = erf(load / (2 sqrt(G/E*^2))), G/E*^2 = (pi/4) q3_integral, q3_integral = int q^3 C(q)
// dq (dimensionless; C in Persson's convention, docs/theory.md section 1).
Real persson_area_fraction_psd(Real load, Real q3_integral);

// int q^3 C(q) dq of the lattice spectrum: (1/(2 pi)) sum_k |q_k|^2 C(q_k) dqx dqy over the full lattice (the
// isotropic continuum identity int d^2q q^2 C = 2 pi int q^3 C dq, applied to the lattice sum).
Real persson_q3_integral(const FourierCoefficients& coefficients);

// The curve at the requested loads (finite, > 0, ascending): method "persson", separation and spots NaN.
LoadAreaCurve persson_curve(const SpectralMoments& moments, std::span<const Real> loads);

}  // namespace contactbench
