// Greenwood–Williamson summits that stick (docs/theory.md section 10.4): the summit population of the
// project's GW (theories/greenwood_williamson.hpp, McCool's density eta, radius beta and Gaussian heights of
// mean ys and deviation sigma_s) in which every summit makes its own adhesive contact with the flat, as in
// Fuller & Tabor (Proc. R. Soc. A 345, 327, 1975). What a summit does is the caller's single-sphere model
// (JKR: theories/fuller_tabor.hpp; Maugis–Dugdale: theories/maugis_greenwood_williamson.hpp), given in the
// dimensionless units of Johnson and Greenwood (J. Colloid Interface Sci. 192, 326, 1997) by its state on
// its branch in contact as a function of the contact radius ā, and by a non-contact attraction linear in
// the approach. Summits do not interact (as in GW).
//
// At the flat's separation d (from the mean plane, t = (d − ys)/sigma_s), a summit of height z has the
// approach δ = z − d, δ̄ = δ/S_δ. With c = sigma_s/S_δ and the summits' normalised heights s = t + δ̄/c
// (density eta φ(s), φ the standard normal density):
//   P/(E* A0) = eta S_P/E* [∫ P̄(ā) φ(s(ā)) s'(ā) dā  +  ∫ P̄_out(δ̄(s)) φ(s) ds],
//   A/A0      = eta π S_a² ∫ ā² φ(s(ā)) s'(ā) dā,          N/A0 = eta F_0(s(ā_first)),
// the contact integrals over ā from the first radius of the branch (where the summits in contact begin)
// up, the non-contact one over the summits within reach of the attraction and not in contact.
// Quadrature: 32 panels, even in s, over s in [max(s_first, −15), max(s_first, 0) + 12] (outside, φ is below
// 1e-31 of its peak), each mapped to ā and integrated by 10-point Gauss–Legendre in ā, where the integrand is
// smooth (also at the first radius when s'(ā) vanishes there); the non-contact part by Gauss–Legendre on
// panels of at most 0.5 in s.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "contactbench/core/types.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"
#include "contactbench/theories/maugis_dugdale_sphere.hpp"

namespace contactbench {

// Which summits are in contact, that is the history assumed (the contact of a sticky summit is hysteretic).
enum class AdhesiveBranch {
  // The flat has only come down: a summit is in contact once it touches it (δ > 0), on its branch in
  // contact there; the jump into contact that a summit's own attraction causes a little earlier is not
  // modelled. Under load control, the largest separation with the load (the first a falling flat meets).
  approach,
  // The flat comes back up from a deep contact that every summit in question had touched (Fuller & Tabor's
  // assumption for the pull-off): a summit stays in contact until its approach falls below the point where
  // its branch in contact ends (dδ̄/dā = 0, the jump out of contact under approach control). Under load
  // control, the smallest separation with the load (the first a rising flat meets).
  retract,
};

// The dimensionless state of one summit on its branch in contact: P̄, δ̄ and dδ̄/dā at the radius ā.
struct AdhesiveSummitState {
  Real load = 0;
  Real approach = 0;
  Real approach_slope = 0;
};

struct AdhesiveSummit {
  std::function<AdhesiveSummitState(Real)> at_radius;  // on the branch in contact, ā > 0
  Real first_radius = 0;  // ā where the summits in contact begin (the branch's: touch, or jump out)
  // Out of contact, within reach: P̄_out = −outside_slope (δ̄ − outside_reach) for outside_reach < δ̄ <
  // min(0, δ̄(first_radius)); outside_slope = 0: no attraction out of contact (JKR).
  Real outside_slope = 0;
  Real outside_reach = 0;
  MaugisDugdaleScales scales;  // S_a, S_P, S_δ of the summits' radius, E* and w
};

// The population at one separation.
struct AdhesiveSummitsState {
  Real load = 0;           // P/(E* A0), may be negative (tensile)
  Real area_fraction = 0;  // A/A0, the repulsive contact area, not capped
  Real spot_density = 0;   // N/A0 [1/m^2], summits in contact
};

class AdhesiveSummitPopulation {
 public:
  AdhesiveSummitPopulation(const GwParameters& gw, AdhesiveSummit summit, Real estar);

  const GwParameters& gw() const { return gw_; }
  // The population at the normalised separation t = (d − ys)/sigma_s (any finite t).
  AdhesiveSummitsState at(Real t) const;
  // The normalised separation t in [kGwMinSeparation, kGwMaxSeparation] of each load (> 0, ascending) on
  // the branch: scanned in steps of 1/8 from the far end of the branch (approach: from t = 40 down;
  // retract: from t = −10 up) to the first load at or beyond the request, then Brent's method to 1e-13 of
  // the load. Throws Error naming `method` and the load when the scan never reaches it.
  std::vector<Real> solve(std::span<const Real> loads, AdhesiveBranch branch,
                          const std::string& method) const;
  // The least load of the scan (step 1/8 in t, then golden section) on the retract branch: the pull-off
  // force P/(E* A0) < 0 of the population under load control, and its t.
  std::pair<Real, Real> pull_off() const;

 private:
  Real radius_at_approach(Real approach) const;  // ā on the branch in contact with δ̄(ā) ≈ approach

  GwParameters gw_;
  AdhesiveSummit summit_;
  Real estar_ = 0;
  Real spread_ = 0;                                  // c = sigma_s/S_δ
  Real first_approach_ = 0;                          // δ̄(first_radius)
  std::vector<Real> table_radius_, table_approach_;  // the branch sampled, for the panels' ends
};

// The load-area curve of the population at the requested loads (finite, > 0, ascending) on the branch:
// area capped at 1 as GW's is (and the parameters say from which load), separation d = ys + t sigma_s,
// spots N/A0 x nominal_area. The parameters text begins with `parameters`.
LoadAreaCurve adhesive_summits_curve(const AdhesiveSummitPopulation& population, std::span<const Real> loads,
                                     std::optional<Real> nominal_area, AdhesiveBranch branch,
                                     const std::string& method, std::string parameters);

std::string_view adhesive_branch_name(AdhesiveBranch branch);

}  // namespace contactbench
