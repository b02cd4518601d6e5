// Whether a rough surface is sticky at all: the criterion of L. Pastewka and M. O. Robbins (Contact between
// rough surfaces and a criterion for macroscopic adhesion, PNAS 111, 3298, 2014, their eq. 10), with their
// repulsive-area constant κ_rep = 2 and their repulsive range d_rep = 4 h'_rms/h''_rms, in the form the
// ContactEngineering Adhesion package's examples evaluate it (docs/theory.md section 10.5):
//   C = (h'_rms E* Δr / (2 w)) (h'_rms² / (h''_rms Δr))^(2/3),   sticky (a finite pull-off) when C < 1,
// with h'_rms the areal rms gradient, h''_rms the rms curvature (half the rms Laplacian), Δr the range of the
// attraction and w the work of adhesion. The criterion is derived for short-ranged attraction in the DMT
// regime (Δr much below the surface's heights). The paper's body was not at hand to check the constants
// against; the form above is the one its second author's group evaluates.
#pragma once

#include <string>

#include "contactbench/core/adhesion_law.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

struct PastewkaRobbinsCriterion {
  Real number = 0;         // C: sticky when below 1
  Real rms_gradient = 0;   // h'_rms = sqrt(m2x + m2y)
  Real rms_curvature = 0;  // h''_rms = sqrt(<(∇²h)²>)/2 = sqrt(2 m4/3) for an isotropic surface
  Real range = 0;          // Δr [m]: the law's reach (ρ, or δc = w/σ0)
  bool sticky() const { return number < 1; }
};

// From the surface's moments (isotropic: refused as the theories refuse anisotropy), E* [Pa] and the law.
PastewkaRobbinsCriterion pastewka_robbins_criterion(const SpectralMoments& moments, Real estar,
                                                    const AdhesionLaw& law);

// "Pastewka-Robbins stickiness number C = ... (sticky below 1: ...)" for a method's parameters.
std::string pastewka_robbins_text(const PastewkaRobbinsCriterion& criterion);

}  // namespace contactbench
