// Chang-Etsion-Bogy's elastic-plastic summits (W. R. Chang, I. Etsion and D. B. Bogy, "An elastic-plastic
// model for the contact of rough surfaces", J. Tribol. 109, 257-263, 1987; docs/theory.md section 11.1). A
// summit of radius R is Hertzian up to the critical interference at which yield starts,
//   wc = (pi K H / (2 E*))^2 R,   K = 0.454 + 0.41 nu   (the maximum Hertz pressure K H at yield inception),
// and beyond it deforms plastically with its volume conserved:
//   A1 = pi R w (2 - wc/w),   P1 = K H A1   (mean pressure K H, all of it plastic).
// Known defects, kept as published: the load jumps by 3/2 at w = wc (Hertz's mean pressure there is (2/3) K
// H), and the plastic mean pressure is K H ~ 0.6 H, so its rigid-plastic limit is A/A0 = P/(K H A0), not P/(H
// A0).
#pragma once

#include <span>

#include "contactbench/core/spectrum.hpp"
#include "contactbench/theories/plastic_summits.hpp"

namespace contactbench {

// K = 0.454 + 0.41 nu (Chang, Etsion and Bogy 1987, after the Hertz stress field at yield inception).
Real hardness_coefficient(Real poisson_ratio);
// wc = (pi K h / 2)^2 R, h = H/E*; infinite without a hardness.
Real critical_interference(Real radius, Real hardness_over_estar, Real poisson_ratio);

// The law of one summit of radius R (h = H/E*; kNoHardness: Hertz).
AsperityLaw chang_etsion_bogy_law(Real radius, Real hardness_over_estar, Real poisson_ratio);

// The curve on McCool's GW summits (method "ceb"), plastic columns: the summits beyond wc.
PlasticCurve chang_etsion_bogy_curve(const SpectralMoments& moments, std::span<const Real> loads,
                                     Real hardness_over_estar, Real poisson_ratio, Real nominal_area);

}  // namespace contactbench
