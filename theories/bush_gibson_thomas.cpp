#include "contactbench/theories/bush_gibson_thomas.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/brent_root.hpp"
#include "contactbench/theories/elliptic_integrals.hpp"
#include "contactbench/theories/gaussian_tail_integrals.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/theory_curve.hpp"

namespace contactbench {
namespace {

constexpr Real nan = std::numeric_limits<Real>::quiet_NaN();

// Absolute floor of the bracket width in zeta = d/sqrt(m0).
constexpr Real kZetaBracketFloor = 1e-15;
// The axis ratio: ln of the curvature ratio to 1e-15 gives (b/a)^2 to about 1e-15.
constexpr Real kShapeTolerance = 1e-15;
// Quadrature in u = rho^2: tanh-sinh over tau in [-kShapeRange, kShapeRange] with step kShapeStep at level 0.
// At |tau| = 4 the nodes are e^-86 from the ends, where the integrand is below 1e-40 of its size. The step
// 1/16 is set by the narrow exp(-3 x^2 u/2) at the largest x: 1/8 leaves 1e-5 at alpha = 1.6, 1/16 and 1/32
// agree to 3e-13.
constexpr Real kShapeRange = 4;
constexpr Real kShapeStep = 1.0 / 16;
// Quadrature in x = kbar/sqrt(m4): the step in x at the far end of the range is the width (standard
// deviation) of the summits that contribute at one separation divided by kCurvatureStepsPerWidth, and the
// range reaches kCurvatureMargin beyond the curvature of the summits that carry the load at the largest
// separation (the weight exp(-3 x^2/4) has fallen by more than e^-75 there). 3 and 6 steps per width agree
// to 3e-13 (tests/test_bgt.cpp, QuadratureConverges).
constexpr Real kCurvatureStepsPerWidth = 3;
constexpr Real kCurvatureMargin = 10;
// Terms whose upper bound is this far (in ln) below the largest bound are left out of a sum: the largest term
// is at most ~12 below the largest bound, so what is left out is below e^-68 of the sum per node.
constexpr Real kNegligibleLog = 80;

// The square of the axis ratio, y = (b/a)^2 = 1 - e^2, of the elliptic Hertz contact whose curvature ratio
// B/A = lambda >= 1 (Johnson 1985, eq. 4.39): B/A = [(a/b)^2 E - K]/(K - E) = R_D(0, 1, y)/R_D(0, y, 1)
// (DLMF 19.25.1: K - E = (m/3) R_D(0, y, 1), E/y - K = (m/3) R_D(0, 1, y)), with no cancellation at y -> 1.
Real axis_ratio_squared(Real log_lambda) {
  if (log_lambda == 0) return 1;
  auto residual = [log_lambda](Real log_y) {
    const Real y = std::exp(log_y);
    return std::log(carlson_rd(0, 1, y) / carlson_rd(0, y, 1)) - log_lambda;
  };
  // The ratio grows from 1 at y = 1 to infinity (about 2/(y ln(16/y))) as y -> 0.
  Real low = -log_lambda - 1, f_low = residual(low);
  while (f_low <= 0) {
    low -= 2;
    f_low = residual(low);
  }
  return std::exp(find_root(residual, low, 0, f_low, -log_lambda, kShapeTolerance, 1e-16));
}

// c_A B and c_P B^(1/2) of an elliptic Hertz contact with B/A = lambda, in the form (c_A A, c_P A^(1/2)):
// a^2 = delta (K - E)/(A e^2 K), area = pi a^2 sqrt(1 - e^2), P/E* = (2 pi/3) A a^3 e^2/(K - E) (Johnson
// 1985, eqs. 4.39), with K = R_F(0, y, 1) and (K - E)/e^2 = R_D(0, y, 1)/3.
struct ScaledHertz {
  Real area = 0;  // c_A A
  Real load = 0;  // c_P A^(1/2)
  Real y = 1;     // (b/a)^2
};
ScaledHertz scaled_hertz(Real log_lambda) {
  ScaledHertz h;
  h.y = axis_ratio_squared(log_lambda);
  const Real rf = carlson_rf(0, h.y, 1), k_minus_e_over_m = carlson_rd(0, h.y, 1) / 3;
  h.area = pi * std::sqrt(h.y) * k_minus_e_over_m / rf;
  h.load = 2 * pi / 3 * std::sqrt(k_minus_e_over_m) / (rf * std::sqrt(rf));
  return h;
}

}  // namespace

EllipticHertz elliptic_hertz(Real kappa1, Real kappa2) {
  if (!(std::isfinite(kappa1) && std::isfinite(kappa2) && kappa1 > 0 && kappa1 <= kappa2))
    throw Error("elliptic_hertz: the principal curvatures must satisfy 0 < kappa1 <= kappa2 (finite), got " +
                format_number(kappa1) + ", " + format_number(kappa2));
  const ScaledHertz h = scaled_hertz(std::log(kappa2 / kappa1));
  const Real a = kappa1 / 2;  // Johnson's A
  return {.area_coefficient = h.area / a,
          .load_coefficient = h.load / std::sqrt(a),
          .axis_ratio = std::sqrt(h.y)};
}

BushGibsonThomas::BushGibsonThomas(const IsotropicMoments& m, BgtQuadrature quadrature) : moments_(m) {
  auto positive = [](Real v) { return std::isfinite(v) && v > 0; };
  if (!(positive(m.m0) && positive(m.m2) && positive(m.m4)))
    throw Error("bgt: the moments m0, m2, m4 must be finite and > 0, got " + format_number(m.m0) + ", " +
                format_number(m.m2) + ", " + format_number(m.m4));
  if (!(quadrature.level >= 0 && quadrature.level <= 6))
    throw Error("bgt: the quadrature level must lie in [0, 6], got " + std::to_string(quadrature.level));
  alpha_ = m.m0 * m.m4 / (m.m2 * m.m2);
  if (!(alpha_ > 1.5))
    throw Error(
        "bgt: Nayak's bandwidth alpha = m0 m4/m2^2 = " + format_number(alpha_) +
        " must exceed 1.5, or the variance m0 (1 - 3/(2 alpha)) of the summit heights at given curvature "
        "is not positive");
  // docs/theory.md section 5: z given u is N(mu, s^2), mu = -(3 m2/(2 m4)) u, s^2 = m0 (1 - 3/(2 alpha)).
  const Real sigma = std::sqrt(1 - 1.5 / alpha_);  // s/sqrt(m0)
  s_ = std::sqrt(m.m0) * sigma;
  const Real slope = 1.5 / std::sqrt(alpha_);  // mu/sqrt(m0) = slope * x

  // Shape nodes: u = rho^2 = 1/(1 + exp(-2q)), q = (pi/2) sinh(tau) (tanh-sinh), with 1 - u kept exactly.
  const Real shape_step = kShapeStep / std::pow(2.0, quadrature.level);
  const Index half = static_cast<Index>(std::lround(kShapeRange / shape_step));
  std::vector<Real> shape_u, shape_weight, area_factor, load_factor;
  for (Index k = -half; k <= half; ++k) {
    const Real tau = static_cast<Real>(k) * shape_step, q = pi / 2 * std::sinh(tau);
    const Real eq = std::exp(-2 * std::abs(q));
    const Real small = eq / (1 + eq);  // the end nearer the node
    const Real u = q < 0 ? small : 1 - small, one_minus_u = q < 0 ? 1 - small : small;
    // du = (pi/4) cosh(tau)/cosh(q)^2 dtau = pi cosh(tau) small (1 - small) dtau; the integrand's 1/2 from
    // rho drho = du/2 and the factor (1 - rho^2) = 1 - u are included here.
    const Real weight = shape_step * pi * std::cosh(tau) * small * (1 - small) * 0.5 * one_minus_u;
    const Real rho = std::sqrt(u), one_minus_rho = one_minus_u / (1 + rho);
    // kappa1 = kbar (1 - rho), kappa2 = kbar (1 + rho): Johnson's A = kbar (1 - rho)/2.
    const ScaledHertz h = scaled_hertz(std::log1p(rho) - std::log(one_minus_rho));
    shape_u.push_back(u);
    shape_weight.push_back(weight);
    area_factor.push_back(2 * h.area / one_minus_rho);             // c_A kbar
    load_factor.push_back(h.load * std::sqrt(2 / one_minus_rho));  // c_P kbar^(1/2)
  }
  shape_nodes_ = static_cast<Index>(shape_u.size());

  // Curvature nodes: x = v^2, trapezoidal rule in v on (0, v_max]; the v = 0 node carries no weight.
  // The summits that carry the load at normalised separation zeta have x near the maximum of
  // -3 x^2/4 - (zeta - slope x)^2/(2 sigma^2), at slope zeta/(1.5 sigma^2 + slope^2), with standard
  // deviation 1/sqrt(1.5 + slope^2/sigma^2).
  const Real x_peak = slope * kBgtMaxSeparation / (1.5 * sigma * sigma + slope * slope);
  const Real width = 1 / std::sqrt(1.5 + slope * slope / (sigma * sigma));
  const Real v_max = std::sqrt(x_peak + kCurvatureMargin);
  const Real v_step = width / kCurvatureStepsPerWidth / (2 * v_max) / std::pow(2.0, quadrature.level);
  curvature_nodes_ = static_cast<Index>(std::ceil(v_max / v_step));
  // ln of the constant factors (see the header): C (m4/m2) for N/A0, C sqrt(alpha) sigma for A/A0 and
  // C alpha^(3/4) sqrt(m2) sigma^(3/2) for P/(E* A0), C = 3 sqrt3/(4 pi^1.5).
  const Real log_c = std::log(3 * std::numbers::sqrt3 / (4 * pi * std::sqrt(pi)));
  const Real log_spot = log_c + std::log(m.m4 / m.m2);
  const Real log_area = log_c + 0.5 * std::log(alpha_) + std::log(sigma);
  const Real log_load = log_c + 0.75 * std::log(alpha_) + 0.5 * std::log(m.m2) + 1.5 * std::log(sigma);
  for (Index i = 1; i <= curvature_nodes_; ++i) {
    const Real v = static_cast<Real>(i) * v_step, x = v * v;
    Real spot = 0, area = 0, load = 0;
    for (Index k = 0; k < shape_nodes_; ++k) {
      const Real wk = shape_weight[k] * std::exp(-1.5 * x * x * shape_u[k]);
      spot += wk;
      area += wk * area_factor[k];
      load += wk * load_factor[k];
    }
    // dx = 2 v dv; the x-dependence x^4 exp(-3 x^2/4), with 1/kbar in c_A and kbar^(-1/2) in c_P.
    const Real log_common = std::log(2 * v * v_step) - 0.75 * x * x, log_x = std::log(x);
    mu_.push_back(std::sqrt(m.m0) * slope * x);
    log_spot_weight_.push_back(log_spot + log_common + 4 * log_x + std::log(spot));
    log_area_weight_.push_back(log_area + log_common + 3 * log_x + std::log(area));
    log_load_weight_.push_back(log_load + log_common + 3.5 * log_x + std::log(load));
  }
}

Real BushGibsonThomas::log_sum(const std::vector<Real>& log_weight, Real n, Real d) const {
  // F_n(t) <= F_n(0) exp(-t^2/2) for t >= 0 (F_n = phi(t) I_n(t), I_n decreasing): a cheap upper bound.
  const Real log_f0 = log_gaussian_tail_integral(n, 0);
  const std::size_t count = log_weight.size();
  std::vector<Real> bound(count), t(count);
  Real largest_bound = -std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < count; ++i) {
    t[i] = (d - mu_[i]) / s_;
    bound[i] = t[i] > 0 ? log_weight[i] + log_f0 - 0.5 * t[i] * t[i]
                        : log_weight[i] + log_gaussian_tail_integral(n, t[i]);
    largest_bound = std::max(largest_bound, bound[i]);
  }
  Real largest = -std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < count; ++i) {
    if (bound[i] < largest_bound - kNegligibleLog) {
      bound[i] = -std::numeric_limits<Real>::infinity();
      continue;
    }
    if (t[i] > 0) bound[i] = log_weight[i] + log_gaussian_tail_integral(n, t[i]);
    largest = std::max(largest, bound[i]);
  }
  Real sum = 0;
  for (std::size_t i = 0; i < count; ++i)
    sum += std::exp(bound[i] - largest);
  return largest + std::log(sum);
}

Real BushGibsonThomas::summit_density() const {
  Real sum = 0;
  for (const Real lw : log_spot_weight_)
    sum += std::exp(lw);
  return sum;
}

Real BushGibsonThomas::mean_summit_height() const {
  Real sum = 0, moment = 0;
  for (std::size_t i = 0; i < mu_.size(); ++i) {
    sum += std::exp(log_spot_weight_[i]);
    moment += std::exp(log_spot_weight_[i]) * mu_[i];
  }
  return moment / sum;
}

Real BushGibsonThomas::spot_density(Real d) const {
  return std::exp(log_sum(log_spot_weight_, 0, d));
}
Real BushGibsonThomas::log_area_fraction(Real d) const {
  return log_sum(log_area_weight_, 1, d);
}
Real BushGibsonThomas::area_fraction(Real d) const {
  return std::exp(log_area_fraction(d));
}
Real BushGibsonThomas::log_load(Real d) const {
  return log_sum(log_load_weight_, 1.5, d);
}
Real BushGibsonThomas::load(Real d) const {
  return std::exp(log_load(d));
}

Real BushGibsonThomas::stiffness(Real d) const {
  return 1.5 / s_ * std::exp(log_sum(log_load_weight_, 0.5, d));
}

Real BushGibsonThomas::solve_separation(Real load) const {
  if (!(std::isfinite(load) && load > 0))
    throw Error("bgt: a load P/(E* A0) must be finite and > 0, got " + format_number(load));
  const Real scale = std::sqrt(moments_.m0), target = std::log(load);
  auto residual = [this, scale, target](Real zeta) { return log_load(scale * zeta) - target; };
  const Real f_low = residual(kBgtMinSeparation), f_high = residual(kBgtMaxSeparation);
  if (f_low < 0)
    throw Error("bgt: the load P/(E* A0) = " + format_number(load) +
                " is beyond the largest load reachable, " +
                format_number(this->load(scale * kBgtMinSeparation)) +
                " at d/sqrt(m0) = " + format_number(kBgtMinSeparation));
  if (f_high > 0)
    throw Error("bgt: the load P/(E* A0) = " + format_number(load) +
                " is below the smallest load solved for, exp(" +
                format_number(log_load(scale * kBgtMaxSeparation)) +
                ") at d/sqrt(m0) = " + format_number(kBgtMaxSeparation));
  return scale * find_root(residual, kBgtMinSeparation, kBgtMaxSeparation, f_low, f_high, kLogLoadTolerance,
                           kZetaBracketFloor);
}

LoadAreaCurve bgt_curve(const SpectralMoments& moments, std::span<const Real> loads,
                        std::optional<Real> nominal_area) {
  TheoryCurve curve("bgt");
  const IsotropicMoments m = isotropic_moments(moments, curve.method());
  const BushGibsonThomas model(m);
  curve.check_request(loads, nominal_area);
  Real cap_from = nan;  // first load whose A/A0 was capped
  for (const Real load : loads) {
    const Real d = model.solve_separation(load);
    const Real area = model.area_fraction(d);
    if (area > 1 && std::isnan(cap_from)) cap_from = load;
    curve.add(model.load(d), std::min<Real>(area, 1), d,
              nominal_area ? model.spot_density(d) * *nominal_area : nan);
  }
  std::string parameters = describe(m) +
                           "; full Bush-Gibson-Thomas (1975): elliptic Hertz summits with Nayak's "
                           "height-curvature density, separation d solved for each load; quadrature " +
                           std::to_string(model.curvature_nodes()) + " x " +
                           std::to_string(model.shape_nodes()) + " nodes";
  parameters += spots_text(nominal_area);
  if (!std::isnan(cap_from)) {
    // The separation at which BGT's A/A0 reaches 1: A/A0 decreases with d and exceeds 1 at the capped load.
    const Real d_capped = model.solve_separation(cap_from), d_max = kBgtMaxSeparation * std::sqrt(m.m0);
    auto excess = [&model](Real d) { return model.log_area_fraction(d); };
    const Real f_max = excess(d_max);
    const Real d_full = f_max >= 0 ? d_max
                                   : find_root(excess, d_capped, d_max, excess(d_capped), f_max,
                                               kLogLoadTolerance, kZetaBracketFloor * std::sqrt(m.m0));
    parameters += "; capped at A/A0 = 1 for loads >= " + format_number(model.load(d_full)) +
                  " (BGT's A/A0 exceeds 1 beyond)";
  }
  return curve.finish(std::move(parameters));
}

}  // namespace contactbench
