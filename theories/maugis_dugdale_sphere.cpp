#include "contactbench/theories/maugis_dugdale_sphere.hpp"

#include <cmath>
#include <limits>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/brent_root.hpp"

namespace contactbench {

namespace {

// The left side of Maugis' equation for m, less 1: -1 at m = 1, growing without bound with m.
Real radius_ratio_equation(Real m, Real a, Real lambda) {
  const Real s = std::sqrt(m * m - 1), t = std::atan(s);
  return lambda * a * a / 2 * (s + (m * m - 2) * t) + 4 * lambda * lambda * a / 3 * (s * t - m + 1) - 1;
}

// The golden-section minimum of f on [lo, hi] (f unimodal there).
template <class F>
Real minimise(F f, Real lo, Real hi) {
  const Real ratio = (std::sqrt(5.0) - 1) / 2;
  Real x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo), f1 = f(x1), f2 = f(x2);
  for (int k = 0; k < 200 && hi - lo > 1e-14 * hi; ++k) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = f(x2);
    }
  }
  return (lo + hi) / 2;
}

// The smallest ā of the curve sampled on a logarithmic grid where g(ā) is least, refined by golden section.
template <class G>
Real least_on_curve(G g) {
  Real best = 1e-4, best_value = g(best);
  for (Real a = 1e-4; a < 100; a *= 1.02)
    if (const Real v = g(a); v < best_value) {
      best_value = v;
      best = a;
    }
  return minimise(g, best / 1.02, best * 1.02);
}

// ā with value(ā) = target on the rising branch above `from` (value rises there without bound).
template <class G>
Real on_rising_branch(G value, Real target, Real from) {
  if (target < value(from)) return std::numeric_limits<Real>::quiet_NaN();
  Real hi = std::max(2 * from, 1.0);
  while (value(hi) < target)
    hi *= 2;
  auto f = [&](Real a) { return value(a) - target; };
  return find_root(f, from, hi, f(from), f(hi), 0, 1e-15 * hi);
}

}  // namespace

MaugisDugdaleState maugis_dugdale_at_radius(Real a, Real lambda) {
  if (!(a > 0 && lambda > 0 && std::isfinite(a) && std::isfinite(lambda)))
    throw Error("Maugis-Dugdale: the contact radius and lambda must be finite and > 0");
  auto f = [&](Real m) { return radius_ratio_equation(m, a, lambda); };
  Real hi = 2;
  while (f(hi) < 0)
    hi = 1 + 2 * (hi - 1);
  MaugisDugdaleState state;
  state.radius_ratio = find_root(f, 1, hi, -1, f(hi), 0, 1e-15 * hi);
  const Real m = state.radius_ratio, s = std::sqrt(m * m - 1), t = std::atan(s);
  state.load = a * a * a - lambda * a * a * (s + m * m * t);
  state.approach = a * a - 4 * lambda * a * s / 3;
  return state;
}

Real maugis_dugdale_radius_at_approach(Real approach, Real lambda) {
  auto delta = [&](Real a) { return maugis_dugdale_at_radius(a, lambda).approach; };
  return on_rising_branch(delta, approach, least_on_curve(delta));
}

MaugisDugdalePullOff maugis_dugdale_pull_off(Real lambda) {
  auto load = [&](Real a) { return maugis_dugdale_at_radius(a, lambda).load; };
  const Real a = least_on_curve(load);
  return {load(a), a};
}

Real maugis_dugdale_radius_at_load(Real load, Real lambda) {
  auto value = [&](Real a) { return maugis_dugdale_at_radius(a, lambda).load; };
  return on_rising_branch(value, load, maugis_dugdale_pull_off(lambda).contact_radius);
}

MaugisDugdaleScales maugis_dugdale_scales(Real sphere_radius, Real modulus, Real work) {
  const Real k = 4 * modulus / 3;
  return {std::cbrt(M_PI * work * sphere_radius * sphere_radius / k), M_PI * work * sphere_radius,
          std::cbrt(M_PI * M_PI * work * work * sphere_radius / (k * k))};
}

}  // namespace contactbench
