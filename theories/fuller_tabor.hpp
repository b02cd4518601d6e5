// Fuller–Tabor: Greenwood–Williamson summits each a JKR sphere (K. N. G. Fuller, D. Tabor, Proc. R. Soc.
// A 345, 327, 1975; JKR: Johnson, Kendall & Roberts, Proc. R. Soc. A 324, 301, 1971; docs/theory.md
// section 10.4). The summits are the project's GW with McCool's parameters
// (theories/greenwood_williamson.hpp: density, radius and Gaussian heights from the profile moments m0, m2,
// m4), each making the JKR contact of theories/jkr_sphere.hpp with the flat, independently, under the flat's
// approach. JKR needs only the work of adhesion w, so any adhesion law is accepted through its w (its stress
// or range is not used: the JKR limit is that of an attraction of vanishing range). Branches
// (theories/adhesive_summits.hpp): approach, a summit in contact once it touches (its height above the
// separation) at δ̄ = 0, ā = (8/3)^(1/3), P̄ = −4/3; retract, Fuller and Tabor's own assumption for the
// pull-off, a summit in contact until it is pulled to δ̄ = −0.9086 (ā = 6^(−1/3)), where it jumps off.
// No attraction out of contact (JKR's range is zero).
#pragma once

#include <optional>
#include <span>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/theories/adhesive_summits.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"

namespace contactbench {

// The JKR summit of radius beta for E* [Pa] and w [J/m^2] on the branch.
AdhesiveSummit fuller_tabor_summit(Real radius, Real estar, Real work, AdhesiveBranch branch);

// Fuller and Tabor's adhesion parameter θ = E* sigma_s^(3/2) / (beta^(1/2) w) (their 1975 paper, with E*
// for their E and the summit height deviation for their σ): small θ, sticky; θ of a few or more, the
// adhesion is lost to the roughness.
Real fuller_tabor_adhesion_parameter(const GwParameters& gw, Real estar, Real work);

// The curve at the loads (finite, > 0, ascending) for the surface's moments (McCool's summits, refused as
// gw_mccool refuses), E* and w. Method "fuller_tabor"; the parameters say w, θ, the branch, the summits and
// the pull-off force of the retract branch.
LoadAreaCurve fuller_tabor_curve(const SpectralMoments& moments, Real estar, Real work,
                                 std::span<const Real> loads, AdhesiveBranch branch,
                                 std::optional<Real> nominal_area = std::nullopt);

}  // namespace contactbench
