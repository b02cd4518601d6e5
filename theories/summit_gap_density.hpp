// The gap distribution of the summit models (Greenwood-Williamson with McCool's parameters; docs/theory.md
// section 12.8): outside its summit contacts the surface stays undeformed, so the gap at a point of height h
// is d - h, d the flat's separation from the mean plane of the heights at the load (the identification of
// section 12.4, by which the model's mean gap is d). With Gaussian heights of rms sigma,
//   P(g) = exp(-(d - g)^2 / (2 sigma^2)) / (sqrt(2 pi) sigma),   g > 0,
// whose integral over g > 0 is Phi(d/sigma), the fraction of heights below the flat. This is the Gaussian gap
// distribution of the traditional theories that Prodanov, Dapp and Mueller (Tribol. Lett. 53, 433, 2014)
// contrast with the exponential tail the full elastic solution has.
#pragma once

#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

struct SummitGap {
  Real separation = 0;  // d [m], GW-McCool's at the load
  Real rms_height = 0;  // sigma = sqrt(m0) [m]
};

// GW-McCool at load = P/(E* A0) on a surface of these moments. Throws Error where GW-McCool does (a surface
// too anisotropic, alpha <= 0.8968, a load beyond its range).
SummitGap summit_gap_at_load(const SpectralMoments& moments, Real load);

// P(g) [1/m] at gap g >= 0 (0 below).
Real summit_gap_density(const SummitGap& summit, Real gap);

}  // namespace contactbench
