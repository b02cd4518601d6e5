#include "contactbench/theories/fuller_tabor.hpp"

#include <cmath>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/isotropic_moments.hpp"
#include "contactbench/theories/jkr_sphere.hpp"
#include "contactbench/theories/maugis_dugdale_sphere.hpp"
#include "contactbench/theories/number_text.hpp"

namespace contactbench {

AdhesiveSummit fuller_tabor_summit(Real radius, Real estar, Real work, AdhesiveBranch branch) {
  if (!(std::isfinite(work) && work > 0))
    throw Error("fuller_tabor: the work of adhesion must be finite and > 0 J/m^2, got " +
                format_number(work));
  AdhesiveSummit summit;
  summit.at_radius = [](Real a) {
    const JkrState s = jkr_at_radius(a);
    return AdhesiveSummitState{s.load, s.approach, s.approach_slope};
  };
  summit.first_radius =
      branch == AdhesiveBranch::approach ? jkr_radius_at_touch() : jkr_radius_at_separation();
  summit.scales = maugis_dugdale_scales(radius, estar, work);  // the same units as Maugis' (K = 4E*/3)
  return summit;
}

Real fuller_tabor_adhesion_parameter(const GwParameters& gw, Real estar, Real work) {
  return estar * std::pow(gw.sigma_s, 1.5) / (std::sqrt(gw.beta) * work);
}

LoadAreaCurve fuller_tabor_curve(const SpectralMoments& moments, Real estar, Real work,
                                 std::span<const Real> loads, AdhesiveBranch branch,
                                 std::optional<Real> nominal_area) {
  const IsotropicMoments m = isotropic_moments(moments, "fuller_tabor");
  const GwParameters gw = mccool_parameters(m);
  const AdhesiveSummitPopulation population(gw, fuller_tabor_summit(gw.beta, estar, work, branch), estar);
  const AdhesiveSummitPopulation retract(
      gw, fuller_tabor_summit(gw.beta, estar, work, AdhesiveBranch::retract), estar);
  const auto [pull_off, pull_off_t] = retract.pull_off();
  std::string text = describe(m) + "; McCool (1986) summits each a JKR sphere (Fuller & Tabor 1975), w = " +
                     format_number(work) + " J/m^2 (JKR uses w alone), E* = " + format_number(estar) +
                     " Pa; adhesion parameter theta = E* sigma_s^1.5/(beta^0.5 w) = " +
                     format_number(fuller_tabor_adhesion_parameter(gw, estar, work)) +
                     "; pull-off of the retract branch P/(E* A0) = " + format_number(pull_off) +
                     " at d = " + format_number(gw_separation(gw, pull_off_t)) + " m";
  return adhesive_summits_curve(population, loads, nominal_area, branch, "fuller_tabor", std::move(text));
}

}  // namespace contactbench
