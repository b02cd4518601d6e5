#include "contactbench/theories/maugis_greenwood_williamson.hpp"

#include <cmath>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/brent_root.hpp"
#include "contactbench/theories/isotropic_moments.hpp"
#include "contactbench/theories/maugis_dugdale_sphere.hpp"
#include "contactbench/theories/number_text.hpp"

namespace contactbench {

AdhesionLaw equivalent_dugdale_law(const AdhesionLaw& law) {
  validate_adhesion_law(law, "maugis_gw");
  if (law.model == AdhesionModel::dugdale) return law;
  return AdhesionLaw::dugdale(law.work, law.peak_stress());
}

// Maugis' equation F(s, ā) = (λā²/2) A(s) + (4λ²ā/3) B(s) − 1 = 0 in s = √(m² − 1) (docs/theory.md 10.2),
// A = s + (s² − 1) atan s, B = s atan s − m + 1, differentiated without cancellation at small s:
//   dA/ds = 2 s atan s + 2 s²/(1 + s²),   dB/ds = atan s − s³/((1 + s²)(m + 1)),
//   ds/dā = −(λ ā A + (4λ²/3) B) / ((λā²/2) dA/ds + (4λ²ā/3) dB/ds),
//   dδ̄/dā = 2ā − (4/3) λ (s + ā ds/dā)   from δ̄ = ā² − (4/3) λ ā s.
AdhesiveSummitState maugis_dugdale_summit_state(Real a, Real lambda) {
  const MaugisDugdaleState state = maugis_dugdale_at_radius(a, lambda);
  const Real m = state.radius_ratio, s = std::sqrt(std::max<Real>(m * m - 1, 0)), t = std::atan(s);
  const Real big_a = s + (s * s - 1) * t, big_b = s * t - m + 1;
  const Real da = 2 * s * t + 2 * s * s / (1 + s * s), db = t - s * s * s / ((1 + s * s) * (m + 1));
  const Real f_a = lambda * a * big_a + 4 * lambda * lambda / 3 * big_b;
  const Real f_s = lambda * a * a / 2 * da + 4 * lambda * lambda * a / 3 * db;
  const Real ds = f_s > 0 ? -f_a / f_s : 0;
  return {state.load, state.approach, 2 * a - 4 * lambda / 3 * (s + a * ds)};
}

Real maugis_dugdale_radius_at_separation(Real lambda) {
  auto slope = [&](Real a) { return maugis_dugdale_summit_state(a, lambda).approach_slope; };
  // Above λ of about 0.5 the slope is negative at small ā and positive beyond the turn: the first sign
  // change on a logarithmic scan, then Brent. Below, δ̄ rises with ā from ā → 0: there is no turn, the
  // contact of a retracting summit shrinks to a point without a jump (the DMT side of Maugis' map), and the
  // branch is taken from ā = 1e-4 (where a summit's area is 1e-8 of the scale π S_a², and the same
  // smallest radius as theories/maugis_dugdale_sphere.cpp's search).
  Real lo = 1e-4, f_lo = slope(lo);
  if (f_lo >= 0) return lo;
  for (Real hi = lo * 1.05; hi < 1e3; hi *= 1.05) {
    const Real f_hi = slope(hi);
    if (f_lo < 0 && f_hi >= 0) return find_root(slope, lo, hi, f_lo, f_hi, 0, 1e-14 * hi);
    lo = hi;
    f_lo = f_hi;
  }
  throw Error("Maugis-Dugdale: no turn of the branch in contact found for lambda = " + format_number(lambda));
}

AdhesiveSummit maugis_dugdale_summit(Real radius, Real estar, const AdhesionLaw& given,
                                     AdhesiveBranch branch) {
  const AdhesionLaw law = equivalent_dugdale_law(given);
  const Real lambda = law.maugis_parameter(radius, estar);
  AdhesiveSummit summit;
  summit.at_radius = [lambda](Real a) { return maugis_dugdale_summit_state(a, lambda); };
  summit.first_radius = branch == AdhesiveBranch::approach ? maugis_dugdale_radius_at_approach(0, lambda)
                                                           : maugis_dugdale_radius_at_separation(lambda);
  summit.scales = maugis_dugdale_scales(radius, estar, law.work);
  // Out of contact: P̄ = −2 (1 + δ̄/δ̄c) for −δ̄c < δ̄ < 0, δ̄c = δc/S_δ (Derjaguin, rigid sphere).
  const Real reach = law.reach() / summit.scales.approach;
  summit.outside_slope = 2 / reach;
  summit.outside_reach = -reach;
  return summit;
}

LoadAreaCurve maugis_gw_curve(const SpectralMoments& moments, Real estar, const AdhesionLaw& given,
                              std::span<const Real> loads, AdhesiveBranch branch,
                              std::optional<Real> nominal_area) {
  const IsotropicMoments m = isotropic_moments(moments, "maugis_gw");
  const GwParameters gw = mccool_parameters(m);
  const AdhesionLaw law = equivalent_dugdale_law(given);
  const Real lambda = law.maugis_parameter(gw.beta, estar);
  const AdhesiveSummitPopulation population(gw, maugis_dugdale_summit(gw.beta, estar, law, branch), estar);
  const AdhesiveSummitPopulation retract(
      gw, maugis_dugdale_summit(gw.beta, estar, law, AdhesiveBranch::retract), estar);
  const auto [pull_off, pull_off_t] = retract.pull_off();
  std::string text = describe(m) + "; McCool (1986) summits each a Maugis-Dugdale sphere (Maugis 1992), " +
                     (given.model == AdhesionModel::dugdale
                          ? std::string("Dugdale law")
                          : std::string("the exponential law's equal-work, equal-peak-stress Dugdale law")) +
                     " w = " + format_number(law.work) + " J/m^2, sigma0 = " + format_number(law.stress) +
                     " Pa, delta_c = " + format_number(law.reach()) + " m, E* = " + format_number(estar) +
                     " Pa; Maugis' lambda of the summits = " + format_number(lambda) +
                     "; summits out of contact within delta_c pull as rigid spheres (Derjaguin)" +
                     "; pull-off of the retract branch P/(E* A0) = " + format_number(pull_off) +
                     " at d = " + format_number(gw_separation(gw, pull_off_t)) + " m";
  return adhesive_summits_curve(population, loads, nominal_area, branch, "maugis_gw", std::move(text));
}

}  // namespace contactbench
