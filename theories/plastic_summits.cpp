#include "contactbench/theories/plastic_summits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/brent_root.hpp"
#include "contactbench/theories/gaussian_tail_integrals.hpp"
#include "contactbench/theories/isotropic_moments.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/theory_curve.hpp"

namespace contactbench {
namespace {

// 8-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr std::array<Real, 8> kNodes{-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                     -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                     0.7966664774136267,  0.9602898564975363};
constexpr std::array<Real, 8> kWeights{0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                       0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                       0.2223810344533745, 0.1012285362903763};

Real gaussian_density(Real s) {
  return std::exp(-0.5 * s * s) / std::sqrt(2 * std::numbers::pi);
}

void accumulate(AsperityContact& sum, const AsperityContact& c, Real weight) {
  sum.area += weight * c.area;
  sum.load += weight * c.load;
  sum.plastic_area += weight * c.plastic_area;
  sum.plastic_load += weight * c.plastic_load;
}

}  // namespace

AsperityContact summit_sums(const GwParameters& gw, const AsperityLaw& law, Real t) {
  // Where the Gaussian has mass beyond t: up to s = 12 (density e^-72), and far enough past t that
  // exp(-t u) has decayed by e^-50 when t is large.
  const Real u_end = std::max<Real>(12 - t, 0) + 50 / std::max<Real>(t, 4);
  const Real width = std::min<Real>(0.25, 0.5 / std::max<Real>(t, 1));
  std::vector<Real> edges{0};
  for (Real u = width; u < u_end; u += width)
    edges.push_back(u);
  for (const Real w : law.breaks)
    if (w / gw.sigma_s > 0 && w / gw.sigma_s < u_end) edges.push_back(w / gw.sigma_s);
  edges.push_back(u_end);
  std::sort(edges.begin(), edges.end());
  AsperityContact sum;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    const Real a = edges[i], b = edges[i + 1];
    if (!(b > a)) continue;
    for (std::size_t k = 0; k < kNodes.size(); ++k) {
      if (i == 0) {
        // u = v^2 on the first panel: the Hertz load's u^(3/2) becomes smooth in v.
        const Real v = 0.5 * std::sqrt(b) * (kNodes[k] + 1), u = v * v;
        accumulate(sum, law.contact(u * gw.sigma_s),
                   0.5 * std::sqrt(b) * kWeights[k] * 2 * v * gaussian_density(t + u));
      } else {
        const Real u = a + 0.5 * (b - a) * (kNodes[k] + 1);
        accumulate(sum, law.contact(u * gw.sigma_s), 0.5 * (b - a) * kWeights[k] * gaussian_density(t + u));
      }
    }
  }
  sum.area *= gw.eta;
  sum.load *= gw.eta;
  sum.plastic_area *= gw.eta;
  sum.plastic_load *= gw.eta;
  return sum;
}

PlasticCurve plastic_summits_curve(const std::string& method, const SpectralMoments& moments,
                                   std::span<const Real> loads, Real h, Real nominal_area,
                                   const std::function<AsperityLaw(const GwParameters&)>& make_law) {
  TheoryCurve curve(method);
  const IsotropicMoments m = isotropic_moments(moments, method);
  curve.check_request(loads, nominal_area);
  check_hardness(h, loads, method);
  const GwParameters gw = mccool_parameters(m);
  const AsperityLaw law = make_law(gw);
  auto log_load = [&](Real t) { return std::log(summit_sums(gw, law, t).load); };
  PlasticCurve out;
  Real cap_from = std::numeric_limits<Real>::quiet_NaN();
  const Real f_low_base = log_load(kGwMinSeparation), f_high_base = log_load(kGwMaxSeparation);
  for (const Real load : loads) {
    const Real target = std::log(load);
    if (f_low_base < target)
      throw Error(method + ": the load P/(E* A0) = " + format_number(load) +
                  " is beyond the largest load reachable, " + format_number(std::exp(f_low_base)) +
                  " at t = (d - ys)/sigma_s = " + format_number(kGwMinSeparation));
    if (f_high_base > target)
      throw Error(method + ": the load P/(E* A0) = " + format_number(load) +
                  " is below the smallest load solved for, " + format_number(std::exp(f_high_base)) +
                  " at t = " + format_number(kGwMaxSeparation));
    const Real t = find_root([&](Real x) { return log_load(x) - target; }, kGwMinSeparation, kGwMaxSeparation,
                             f_low_base - target, f_high_base - target, kLogLoadTolerance, 1e-15);
    const AsperityContact sums = summit_sums(gw, law, t);
    if (sums.area > 1 && std::isnan(cap_from)) cap_from = load;
    curve.add(sums.load, std::min<Real>(sums.area, 1), gw_separation(gw, t),
              gw_spot_density(gw, t) * nominal_area);
    out.plastic_area_fraction.push_back(std::min<Real>(sums.plastic_area, 1));
    out.plastic_load_fraction.push_back(sums.plastic_load / sums.load);
  }
  std::string parameters = describe(m) + "; McCool (1986) GW summits: eta = " + format_number(gw.eta) +
                           " 1/m^2, beta = " + format_number(gw.beta) +
                           " m, sigma_s = " + format_number(gw.sigma_s) + " m; " + law.text +
                           "; H/E* = " + format_number(h);
  parameters += spots_text(nominal_area);
  if (!std::isnan(cap_from)) parameters += "; A/A0 capped at 1 from the load " + format_number(cap_from);
  out.curve = curve.finish(std::move(parameters));
  return out;
}

}  // namespace contactbench
