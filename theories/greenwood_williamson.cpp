#include "contactbench/theories/greenwood_williamson.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/brent_root.hpp"
#include "contactbench/theories/gaussian_tail_integrals.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/theory_curve.hpp"

namespace contactbench {
namespace {

// McCool (1986) after Nayak (1971): the summit height variance is (1 - 0.8968/alpha) m0.
constexpr Real kNayakSummitVariance = 0.8968;
// Absolute floor of the bracket width in t (the relative floor 4 eps |t| comes first except near t = 0).
constexpr Real kTBracketFloor = 1e-15;

// ln of the prefactors of A/A0 and P/(E* A0) (Greenwood & Williamson 1966, docs/theory.md section 5).
Real log_area_prefactor(const GwParameters& gw) {
  return std::log(pi * gw.eta * gw.beta * gw.sigma_s);
}
Real log_load_prefactor(const GwParameters& gw) {
  return std::log(4.0 / 3.0 * gw.eta) + 0.5 * std::log(gw.beta) + 1.5 * std::log(gw.sigma_s);
}

std::string describe(const GwParameters& gw) {
  return "eta = " + format_number(gw.eta) + " 1/m^2, beta = " + format_number(gw.beta) +
         " m, sigma_s = " + format_number(gw.sigma_s) + " m, ys = " + format_number(gw.ys) + " m";
}

// The t in [kGwMinSeparation, kGwMaxSeparation] with P/(E* A0) = load; errors name `method`.
Real solve_separation(const GwParameters& gw, Real load, const std::string& method) {
  if (!(std::isfinite(load) && load > 0))
    throw Error(method + ": a load P/(E* A0) must be finite and > 0, got " + format_number(load));
  const Real target = std::log(load);
  auto residual = [&gw, target](Real t) { return gw_log_load(gw, t) - target; };
  const Real f_low = residual(kGwMinSeparation), f_high = residual(kGwMaxSeparation);
  if (f_low < 0)
    throw Error(method + ": the load P/(E* A0) = " + format_number(load) +
                " is beyond the largest load reachable, " + format_number(gw_load(gw, kGwMinSeparation)) +
                " at t = (d - ys)/sigma_s = " + format_number(kGwMinSeparation));
  if (f_high > 0)
    throw Error(method + ": the load P/(E* A0) = " + format_number(load) +
                " is below the smallest load solved for, exp(" +
                format_number(gw_log_load(gw, kGwMaxSeparation)) +
                ") at t = (d - ys)/sigma_s = " + format_number(kGwMaxSeparation));
  return find_root(residual, kGwMinSeparation, kGwMaxSeparation, f_low, f_high, kLogLoadTolerance,
                   kTBracketFloor);
}

// The curve of GW summits `gw`; its parameters text begins with `prefix`.
LoadAreaCurve solve_curve(const GwParameters& gw, std::span<const Real> loads,
                          std::optional<Real> nominal_area, TheoryCurve curve, const std::string& prefix) {
  validate(gw);
  curve.check_request(loads, nominal_area);
  const std::string& method = curve.method();
  Real cap_from = std::numeric_limits<Real>::quiet_NaN();  // first load whose A/A0 was capped
  for (const Real load : loads) {
    const Real t = solve_separation(gw, load, method);
    const Real area = gw_area_fraction(gw, t);
    if (area > 1 && std::isnan(cap_from)) cap_from = load;
    curve.add(gw_load(gw, t), std::min<Real>(area, 1), gw_separation(gw, t),
              nominal_area ? gw_spot_density(gw, t) * *nominal_area : std::numeric_limits<Real>::quiet_NaN());
  }
  std::string parameters =
      prefix + "GW summits: " + describe(gw) + "; separation d = ys + t sigma_s solved for each load";
  parameters += spots_text(nominal_area);
  if (!std::isnan(cap_from)) {
    // The load at which GW's A/A0 reaches 1: A/A0 decreases with t, and exceeds 1 at the capped load's t.
    const Real log_area_1 = log_area_prefactor(gw);
    auto excess = [log_area_1](Real t) { return log_area_1 + log_gaussian_tail_integral(1, t); };
    const Real t_capped = solve_separation(gw, cap_from, method);
    const Real f_max = excess(kGwMaxSeparation);
    const Real t_full = f_max >= 0 ? kGwMaxSeparation
                                   : find_root(excess, t_capped, kGwMaxSeparation, excess(t_capped), f_max,
                                               kLogLoadTolerance, kTBracketFloor);
    parameters += "; capped at A/A0 = 1 for loads >= " + format_number(gw_load(gw, t_full)) +
                  " (GW's A/A0 exceeds 1 beyond)";
  }
  return curve.finish(std::move(parameters));
}

}  // namespace

void validate(const GwParameters& gw) {
  auto positive = [](Real v) { return std::isfinite(v) && v > 0; };
  if (!positive(gw.eta))
    throw Error("GW: summit density eta must be finite and > 0 1/m^2, got " + format_number(gw.eta));
  if (!positive(gw.beta))
    throw Error("GW: summit radius beta must be finite and > 0 m, got " + format_number(gw.beta));
  if (!positive(gw.sigma_s))
    throw Error("GW: summit height deviation sigma_s must be finite and > 0 m, got " +
                format_number(gw.sigma_s));
  if (!std::isfinite(gw.ys))
    throw Error("GW: mean summit height ys must be finite, got " + format_number(gw.ys));
}

Real gw_separation(const GwParameters& gw, Real t) {
  return gw.ys + t * gw.sigma_s;
}

// Greenwood & Williamson (1966), docs/theory.md section 5: N/A0 = eta F_0(t).
Real gw_spot_density(const GwParameters& gw, Real t) {
  return gw.eta * gaussian_tail_integral(0, t);
}

// A/A0 = pi eta beta sigma_s F_1(t).
Real gw_area_fraction(const GwParameters& gw, Real t) {
  return std::exp(log_area_prefactor(gw) + log_gaussian_tail_integral(1, t));
}

// P/(E* A0) = (4/3) eta beta^(1/2) sigma_s^(3/2) F_{3/2}(t).
Real gw_log_load(const GwParameters& gw, Real t) {
  return log_load_prefactor(gw) + log_gaussian_tail_integral(1.5, t);
}
Real gw_stiffness(const GwParameters& gw, Real t) {
  return 2 * gw.eta * std::sqrt(gw.beta * gw.sigma_s) * gaussian_tail_integral(0.5, t);
}
Real gw_load(const GwParameters& gw, Real t) {
  return std::exp(gw_log_load(gw, t));
}

GwParameters mccool_parameters(const IsotropicMoments& m) {
  const Real alpha = m.m0 * m.m4 / (m.m2 * m.m2);
  if (!(alpha > kNayakSummitVariance))
    throw Error("gw_mccool: Nayak's bandwidth alpha = m0 m4/m2^2 = " + format_number(alpha) +
                " must exceed 0.8968, or the summit height variance (1 - 0.8968/alpha) m0 is not positive");
  // McCool, Wear 107 (1986), from Nayak (1971).
  GwParameters gw;
  gw.eta = m.m4 / (6 * pi * std::numbers::sqrt3 * m.m2);
  gw.beta = 3.0 / 8.0 * std::sqrt(pi / m.m4);
  gw.sigma_s = std::sqrt((1 - kNayakSummitVariance / alpha) * m.m0);
  gw.ys = 4 * m.m2 / std::sqrt(pi * m.m4);
  return gw;
}

GwParameters mccool_parameters(const SpectralMoments& moments) {
  return mccool_parameters(isotropic_moments(moments, "gw_mccool"));
}

Real gw_solve_separation(const GwParameters& gw, Real load) {
  validate(gw);
  return solve_separation(gw, load, "GW");
}

LoadAreaCurve greenwood_williamson_curve(const GwParameters& gw, std::span<const Real> loads,
                                         std::optional<Real> nominal_area) {
  return solve_curve(gw, loads, nominal_area, TheoryCurve("greenwood_williamson"), "");
}

LoadAreaCurve gw_mccool_curve(const SpectralMoments& moments, std::span<const Real> loads,
                              std::optional<Real> nominal_area) {
  TheoryCurve curve("gw_mccool");
  const IsotropicMoments m = isotropic_moments(moments, curve.method());
  const GwParameters gw = mccool_parameters(m);
  return solve_curve(gw, loads, nominal_area, std::move(curve), describe(m) + "; McCool (1986) ");
}

}  // namespace contactbench
