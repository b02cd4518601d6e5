// Majumdar and Bhushan's elastic-plastic fractal model (A. Majumdar and B. Bhushan, "Fractal model of
// elastic-plastic contact between rough surfaces", J. Tribol. 113, 1-11, 1991), the one the seed paper cites;
// docs/theory.md section 11.5, with its known criticisms. The profile is a Weierstrass-Mandelbrot function of
// fractal dimension D (1 < D < 2) and roughness G, whose one-sided power spectrum in the spatial frequency f
// is S(f) = G^(2(D-1)) / (2 ln gamma) f^-(5-2D), gamma = 1.5. Contact spots of real area a follow the island
// law n(a) = (D/2) aL^(D/2) a^-(D/2+1) up to the largest spot aL, so that A = D/(2-D) aL. A spot is plastic
// below the critical area ac = G^2 / (H/(2E*))^(2/(D-1)) (carrying H a) and elastic above it (carrying (4
// sqrt(pi)/3) E* G^(D-1) a^((3-D)/2)):
//   P/E* = (4 sqrt(pi)/3) G^(D-1) D/(3-2D) aL^(D/2) [aL^((3-2D)/2) - ac^((3-2D)/2)] + (H/E*) D/(2-D) aL^(D/2)
//   ac^((2-D)/2)
// when aL > ac; when aL <= ac every spot is plastic and P = H A. These are the forms as commonly restated
// (the 1991 paper's prefactors are quoted, not re-derived here).
#pragma once

#include <span>

#include "contactbench/core/surface.hpp"
#include "contactbench/theories/plastic_curve.hpp"

namespace contactbench {

struct FractalParameters {
  Real dimension = 0;  // D of the profile, 1 < D < 2 (D = 2 - Hurst for a self-affine surface)
  Real roughness = 0;  // G [m]
};

// D and G fitted (least squares in log-log) to the mean of the x and y profile power spectra of the surface
// (core/spectrum.hpp, converted to MB's one-sided spectrum in the frequency f = q/(2 pi): S(f) = 4 pi C1(q))
// over q in [q_max/30, q_max/4]: below the top quarter, where the generator's radial cut (docs/theory.md 2.2)
// steepens the profile spectrum (over [q_max/30, q_max] the fit read D about 1 less for H = 0.5 and 0.8).
// Throws Error when the fitted D is outside (1, 2).
FractalParameters fit_fractal_parameters(const Surface& surface);

// Real contact area fraction and both load parts at largest spot aL [m^2], per nominal area A0 [m^2].
struct FractalContact {
  Real area = 0;          // A/A0
  Real elastic_load = 0;  // P_el/(E* A0)
  Real plastic_load = 0;  // P_pl/(E* A0)
  Real plastic_area = 0;  // A_pl/A0
};
FractalContact majumdar_bhushan_contact(const FractalParameters& fractal, Real hardness_over_estar,
                                        Real largest_spot, Real nominal_area);

// The curve (method "majumdar_bhushan") at the requested loads (finite, > 0, ascending, below h), each solved
// for aL. Refuses h = kNoHardness when D >= 1.5: the elastic load of the small spots diverges (section 11.5).
PlasticCurve majumdar_bhushan_curve(const FractalParameters& fractal, std::span<const Real> loads, Real h,
                                    Real nominal_area);

}  // namespace contactbench
