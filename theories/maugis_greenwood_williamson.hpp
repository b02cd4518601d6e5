// Maugis–Greenwood–Williamson: Greenwood–Williamson summits each a Maugis–Dugdale sphere (summits: the
// project's GW with McCool's parameters, theories/greenwood_williamson.hpp; each summit: D. Maugis,
// J. Colloid Interface Sci. 150, 243, 1992, through theories/maugis_dugdale_sphere.hpp; the idea of GW
// summits with Maugis' law is Maugis' own, Contact, Adhesion and Rupture of Elastic Solids, Springer 2000,
// ch. 6, and K. L. Johnson's review, Tribol. Int. 31, 413, 1998; docs/theory.md section 10.4). All summits
// share McCool's radius beta, so one Maugis parameter λ = 2σ0 (9 beta/(16π w E*²))^(1/3) holds for all.
// Summits in contact follow Maugis' branch in contact (theories/adhesive_summits.hpp: approach, from the
// touch δ̄ = 0; retract, until dδ̄/dā = 0). Summits out of contact but within the Dugdale range δc = w/σ0
// of the flat (gap h0 = −δ < δc) pull as rigid spheres would (Derjaguin's approximation, the DMT
// non-contact force of a Dugdale law): F = 2π beta σ0 (δc − h0), that is P̄ = −2 (1 − h0/δc); this neglects
// the deformation their own attraction causes, exact as λ → 0 and an underestimate near contact at larger
// λ (where its share of the load vanishes with the range, δc/S_δ ∝ 1/λ).
// Laws: Dugdale as given; the exponential law (w/ρ) exp(−g/ρ) through the Dugdale law of equal work and
// equal peak stress (σ0 = w/ρ, δc = ρ), which is what Maugis' parameter of core/adhesion_law.hpp uses too.
#pragma once

#include <optional>
#include <span>

#include "contactbench/core/adhesion_law.hpp"
#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/theories/adhesive_summits.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"

namespace contactbench {

// The Dugdale law the summits use: the law itself, or the exponential's equal-work, equal-peak-stress one.
AdhesionLaw equivalent_dugdale_law(const AdhesionLaw& law);

// ā where Maugis' branch in contact turns (dδ̄/dā = 0): a retracting summit jumps out of contact there;
// 1e-4 when the branch has no turn (λ below about 0.5: the contact shrinks to a point without a jump).
Real maugis_dugdale_radius_at_separation(Real lambda);

// dδ̄/dā on Maugis' branch in contact at ā (implicit differentiation of Maugis' equation for m; see the
// .cpp), with the state it belongs to.
AdhesiveSummitState maugis_dugdale_summit_state(Real contact_radius, Real lambda);

// The Maugis–Dugdale summit of radius beta for E* [Pa] and the law (refused unless valid) on the branch.
AdhesiveSummit maugis_dugdale_summit(Real radius, Real estar, const AdhesionLaw& law, AdhesiveBranch branch);

// The curve at the loads (finite, > 0, ascending) for the surface's moments, E* and the law. Method
// "maugis_gw"; the parameters say the Dugdale law used, λ, the branch, the summits and the retract pull-off.
LoadAreaCurve maugis_gw_curve(const SpectralMoments& moments, Real estar, const AdhesionLaw& law,
                              std::span<const Real> loads, AdhesiveBranch branch,
                              std::optional<Real> nominal_area = std::nullopt);

}  // namespace contactbench
