// Persson's theory with a yield stress (B. N. J. Persson, Phys. Rev. Lett. 87, 116101, 2001, "Elastoplastic
// contact between randomly rough surfaces"; docs/theory.md section 11.3). The distribution P(sigma, zeta) of
// the contact pressure diffuses with magnification, dP/dG = d^2P/dsigma^2, from a delta at the nominal
// pressure p = P/A0, with absorbing walls at sigma = 0 (detachment) and at sigma = H (the yield stress, here
// the hardness: a point at H flows plastically and stays in contact at H). At full magnification G = (E*^2/4)
// m2 (as in theories/persson.hpp). Then
//   A_el/A0 = int_0^H P dsigma,   A_pl/A0 = (p - int_0^H sigma P dsigma)/H   (the load the walls carry),
// and A/A0 = A_el/A0 + A_pl/A0. Without a hardness (H -> inf) A/A0 = erf(p/(2 sqrt G)), Persson's elastic
// law.
#pragma once

#include <span>

#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/theories/plastic_curve.hpp"

namespace contactbench {

struct PerssonPlasticAreas {
  Real elastic = 0;  // A_el/A0
  Real plastic = 0;  // A_pl/A0
};

// Both areas at load = p/E*, hardness h = H/E* (> load; kNoHardness: elastic) and profile moment m2, by the
// method of images (fast when G is small against H^2).
PerssonPlasticAreas persson_plastic_areas_images(Real load, Real h, Real m2);
// The same by the Fourier series of the strip 0 < sigma < H (fast when G is large against H^2); h finite.
PerssonPlasticAreas persson_plastic_areas_fourier(Real load, Real h, Real m2);
// The faster of the two for these arguments.
PerssonPlasticAreas persson_plastic_areas(Real load, Real h, Real m2);

// The curve (method "persson_plastic") at the requested loads (finite, > 0, ascending, below h).
PlasticCurve persson_plastic_curve(const SpectralMoments& moments, std::span<const Real> loads, Real h);

}  // namespace contactbench
