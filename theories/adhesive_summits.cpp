#include "contactbench/theories/adhesive_summits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/brent_root.hpp"
#include "contactbench/theories/gaussian_tail_integrals.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/theory_curve.hpp"

namespace contactbench {
namespace {

// 10-point Gauss–Legendre on [-1, 1] (Abramowitz & Stegun table 25.4): exact for polynomials of degree 19.
constexpr std::array<Real, 5> kNodes = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                                        0.8650633666889845, 0.9739065285171717};
constexpr std::array<Real, 5> kWeights = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                                          0.1494513491505806, 0.0666713443086881};

// Summits below s = -15 or above 12 past the start carry φ < 1e-31 of the peak: left out.
constexpr Real kLowestHeight = -15;
constexpr Real kHeightSpan = 12;
constexpr int kContactPanels = 32;
constexpr Real kOutsidePanelWidth = 0.5;
// The scan of the separation (step in t) before Brent's method brackets the requested load.
constexpr Real kScanStep = 0.125;

Real normal_density(Real s) {
  return std::exp(-0.5 * s * s) / std::sqrt(2 * pi);
}

// Gauss–Legendre of f on [a, b].
template <class F>
void gauss_legendre(Real a, Real b, F f) {
  const Real half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (std::size_t i = 0; i < kNodes.size(); ++i) {
    f(mid - half * kNodes[i], half * kWeights[i]);
    f(mid + half * kNodes[i], half * kWeights[i]);
  }
}

}  // namespace

std::string_view adhesive_branch_name(AdhesiveBranch branch) {
  return branch == AdhesiveBranch::approach ? "approach" : "retract";
}

AdhesiveSummitPopulation::AdhesiveSummitPopulation(const GwParameters& gw, AdhesiveSummit summit, Real estar)
    : gw_(gw), summit_(std::move(summit)), estar_(estar) {
  validate(gw_);
  if (!(std::isfinite(estar_) && estar_ > 0))
    throw Error("adhesive summits: E* must be finite and > 0 Pa, got " + format_number(estar_));
  if (!(summit_.first_radius > 0 && summit_.scales.approach > 0))
    throw Error("adhesive summits: the first radius and the scales must be > 0");
  spread_ = gw_.sigma_s / summit_.scales.approach;
  first_approach_ = summit_.at_radius(summit_.first_radius).approach;
  // The branch sampled every 1 % in ā from its first radius: only to place the panels' ends (the
  // quadrature itself evaluates the summit exactly), far enough to cover every approach of t in [-10, 40].
  const Real deepest = first_approach_ + spread_ * (kHeightSpan + 60);
  Real a = summit_.first_radius;
  for (;;) {
    table_radius_.push_back(a);
    table_approach_.push_back(summit_.at_radius(a).approach);
    if (table_approach_.back() > deepest || table_radius_.size() > 100000) break;
    a *= 1.01;
  }
}

Real AdhesiveSummitPopulation::radius_at_approach(Real approach) const {
  if (approach <= table_approach_.front()) return table_radius_.front();
  const auto it = std::upper_bound(table_approach_.begin(), table_approach_.end(), approach);
  if (it == table_approach_.end()) {
    // Beyond the table (a t outside [-10, 40]): the branch rises without bound, Brent from the table's end.
    auto f = [&](Real a) { return summit_.at_radius(a).approach - approach; };
    Real lo = table_radius_.back(), hi = 2 * lo;
    while (f(hi) < 0)
      hi *= 2;
    return find_root(f, lo, hi, f(lo), f(hi), 0, 1e-12 * hi);
  }
  const std::size_t j = static_cast<std::size_t>(it - table_approach_.begin());
  const Real x0 = table_approach_[j - 1], x1 = table_approach_[j];
  return table_radius_[j - 1] + (table_radius_[j] - table_radius_[j - 1]) * (approach - x0) / (x1 - x0);
}

AdhesiveSummitsState AdhesiveSummitPopulation::at(Real t) const {
  if (!std::isfinite(t)) throw Error("adhesive summits: the separation must be finite");
  const Real c = spread_;
  const Real s_first = t + first_approach_ / c;
  Real load = 0, area = 0;
  // Summits in contact, on their branch: panels even in s, integrated in ā.
  const Real s_low = std::max(s_first, kLowestHeight), s_high = std::max(s_low, 0.0) + kHeightSpan;
  Real a_low = s_low == s_first ? summit_.first_radius : radius_at_approach(c * (s_low - t));
  for (int k = 1; k <= kContactPanels; ++k) {
    const Real s_k = s_low + (s_high - s_low) * k / kContactPanels;
    const Real a_high = radius_at_approach(c * (s_k - t));
    gauss_legendre(a_low, a_high, [&](Real a, Real weight) {
      const AdhesiveSummitState state = summit_.at_radius(a);
      const Real density = normal_density(t + state.approach / c) * state.approach_slope / c * weight;
      load += state.load * density;
      area += a * a * density;
    });
    a_low = a_high;
  }
  // Summits out of contact within reach: P̄ = -slope (δ̄ - reach) = -slope c (s - s_reach).
  const Real end = std::min<Real>(0, first_approach_);
  if (summit_.outside_slope > 0 && summit_.outside_reach < end) {
    const Real s_reach = t + summit_.outside_reach / c;
    const Real a = std::max(s_reach, kLowestHeight), b = std::min(t + end / c, -kLowestHeight);
    if (a < b) {
      const int panels = static_cast<int>(std::ceil((b - a) / kOutsidePanelWidth));
      for (int k = 0; k < panels; ++k)
        gauss_legendre(a + (b - a) * k / panels, a + (b - a) * (k + 1) / panels, [&](Real s, Real weight) {
          load -= summit_.outside_slope * c * (s - s_reach) * normal_density(s) * weight;
        });
    }
  }
  const MaugisDugdaleScales& scales = summit_.scales;
  return {gw_.eta * scales.load * load / estar_, gw_.eta * pi * scales.radius * scales.radius * area,
          gw_.eta * gaussian_tail_integral(0, s_first)};
}

std::vector<Real> AdhesiveSummitPopulation::solve(std::span<const Real> loads, AdhesiveBranch branch,
                                                  const std::string& method) const {
  // The scan from the far end of the branch: the flat's path.
  const bool approach = branch == AdhesiveBranch::approach;
  std::vector<Real> ts, ps;
  const int steps = static_cast<int>(std::lround((kGwMaxSeparation - kGwMinSeparation) / kScanStep));
  std::vector<Real> separations;
  std::size_t next = 0;  // scan points computed so far
  auto scan_point = [&](std::size_t k) {
    while (next <= k) {
      const Real t = approach ? kGwMaxSeparation - kScanStep * static_cast<Real>(next)
                              : kGwMinSeparation + kScanStep * static_cast<Real>(next);
      ts.push_back(t);
      ps.push_back(at(t).load);
      ++next;
    }
  };
  for (const Real load : loads) {
    if (!(std::isfinite(load) && load > 0))
      throw Error(method + ": a load P/(E* A0) must be finite and > 0, got " + format_number(load));
    // approach: the first scan point whose load reaches the request; retract: the first below it.
    std::size_t k = 0;
    bool found = false;
    for (; k <= static_cast<std::size_t>(steps); ++k) {
      scan_point(k);
      if (approach ? ps[k] >= load : ps[k] <= load) {
        found = true;
        break;
      }
    }
    if (!found || (!approach && k == 0)) {
      const Real extreme = approach ? *std::max_element(ps.begin(), ps.end()) : ps.front();
      throw Error(method + ": the load P/(E* A0) = " + format_number(load) +
                  " is beyond the largest load reached on the " + std::string(adhesive_branch_name(branch)) +
                  " branch for t = (d - ys)/sigma_s in [" + format_number(kGwMinSeparation) + ", " +
                  format_number(kGwMaxSeparation) + "], " + format_number(extreme));
    }
    if (k == 0) {  // approach: already at t = 40 (a load far below any summit's)
      throw Error(method + ": the load P/(E* A0) = " + format_number(load) +
                  " is below the load at the largest separation solved for, " + format_number(ps[0]) +
                  " at t = (d - ys)/sigma_s = " + format_number(kGwMaxSeparation));
    }
    auto f = [&](Real t) { return at(t).load - load; };
    separations.push_back(
        find_root(f, ts[k - 1], ts[k], ps[k - 1] - load, ps[k] - load, kLogLoadTolerance * load, 1e-15));
  }
  return separations;
}

std::pair<Real, Real> AdhesiveSummitPopulation::pull_off() const {
  Real best_t = kGwMinSeparation, best = at(best_t).load;
  for (Real t = kGwMinSeparation; t <= kGwMaxSeparation; t += kScanStep)
    if (const Real p = at(t).load; p < best) {
      best = p;
      best_t = t;
    }
  // Golden section around the least scan point.
  Real lo = best_t - kScanStep, hi = best_t + kScanStep;
  const Real ratio = (std::sqrt(5.0) - 1) / 2;
  Real x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo), f1 = at(x1).load, f2 = at(x2).load;
  for (int k = 0; k < 60; ++k) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = at(x1).load;
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = at(x2).load;
    }
  }
  const Real t = 0.5 * (lo + hi), p = at(t).load;
  return p < best ? std::pair{p, t} : std::pair{best, best_t};
}

LoadAreaCurve adhesive_summits_curve(const AdhesiveSummitPopulation& population, std::span<const Real> loads,
                                     std::optional<Real> nominal_area, AdhesiveBranch branch,
                                     const std::string& method, std::string parameters) {
  TheoryCurve curve(method);
  curve.check_request(loads, nominal_area);
  const GwParameters& gw = population.gw();
  const std::vector<Real> ts = population.solve(loads, branch, method);
  Real cap_from = std::numeric_limits<Real>::quiet_NaN();
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const AdhesiveSummitsState state = population.at(ts[k]);
    if (state.area_fraction > 1 && std::isnan(cap_from)) cap_from = loads[k];
    curve.add(state.load, std::min<Real>(state.area_fraction, 1), gw_separation(gw, ts[k]),
              nominal_area ? state.spot_density * *nominal_area : std::numeric_limits<Real>::quiet_NaN());
  }
  parameters += "; GW summits: eta = " + format_number(gw.eta) + " 1/m^2, beta = " + format_number(gw.beta) +
                " m, sigma_s = " + format_number(gw.sigma_s) + " m, ys = " + format_number(gw.ys) +
                " m; branch = " + std::string(adhesive_branch_name(branch));
  parameters += spots_text(nominal_area);
  if (!std::isnan(cap_from))
    parameters += "; capped at A/A0 = 1 from the load " + format_number(cap_from) +
                  " (the summits' A/A0 exceeds 1 there, as GW's does)";
  return curve.finish(std::move(parameters));
}

}  // namespace contactbench
