#include "contactbench/theories/persson_plastic.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "contactbench/theories/isotropic_moments.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/theory_curve.hpp"

namespace contactbench {
namespace {

// Terms are dropped once the Gaussian factor is below exp(-kTailExponent): 1e-17 of the first term.
constexpr Real kTailExponent = 40;

// The diffusion "time" at full magnification in units of E*^2: G/E*^2 = m2/4 (section 11.3).
Real diffusion(Real m2) {
  return m2 / 4;
}

// Normal distribution function of variance 2G, and its density.
Real cdf(Real x, Real g) {
  return 0.5 * std::erfc(-x / (2 * std::sqrt(g)));
}
Real density(Real x, Real g) {
  return std::exp(-x * x / (4 * g)) / std::sqrt(4 * pi * g);
}

}  // namespace

// Images: P(s) = sum_k [g(s - p - 2kH) - g(s + p - 2kH)], g the Gaussian of variance 2G. Over [0, H] each
// image of centre c contributes int g(s - c) ds = Phi(H - c) - Phi(-c) and int s g(s - c) ds = c [Phi(H - c)
// - Phi(-c)]
// - 2G [g(H - c) - g(-c)].
PerssonPlasticAreas persson_plastic_areas_images(Real p, Real h, Real m2) {
  const Real g = diffusion(m2);
  if (!std::isfinite(h)) return {.elastic = std::erf(p / (2 * std::sqrt(g))), .plastic = 0};
  const auto images = static_cast<long>(std::ceil(std::sqrt(4 * g * kTailExponent) / (2 * h))) + 1;
  Real area = 0, moment = 0;
  auto add = [&](Real centre, Real sign) {
    const Real mass = cdf(h - centre, g) - cdf(-centre, g);
    area += sign * mass;
    moment += sign * (centre * mass - 2 * g * (density(h - centre, g) - density(-centre, g)));
  };
  for (long k = -images; k <= images; ++k) {
    add(p + 2 * static_cast<Real>(k) * h, 1);
    add(-p + 2 * static_cast<Real>(k) * h, -1);
  }
  return {.elastic = area, .plastic = std::max<Real>(0, (p - moment) / h)};
}

// Fourier: P(s) = (2/H) sum_n sin(n pi p/H) sin(n pi s/H) exp(-(n pi/H)^2 G); int_0^H sin(n pi s/H) ds =
// (H/(n pi)) (1 - (-1)^n) and int_0^H s sin(n pi s/H) ds = (-1)^(n+1) H^2/(n pi).
PerssonPlasticAreas persson_plastic_areas_fourier(Real p, Real h, Real m2) {
  const Real g = diffusion(m2);
  Real area = 0, moment = 0;
  for (long n = 1;; ++n) {
    const Real s = static_cast<Real>(n) * pi / h;
    const Real decay = s * s * g;
    if (decay > kTailExponent && n > 1) break;
    const Real weight = std::sin(s * p) * std::exp(-decay) * 2 / (static_cast<Real>(n) * pi);
    if (n % 2 == 1) area += 2 * weight;
    moment += (n % 2 == 1 ? 1 : -1) * weight * h;
  }
  return {.elastic = area, .plastic = std::max<Real>(0, (p - moment) / h)};
}

PerssonPlasticAreas persson_plastic_areas(Real p, Real h, Real m2) {
  // Images need ~ sqrt(40 G)/H terms, Fourier ~ H sqrt(40/G)/pi: images when G < H^2 (roughly).
  if (!std::isfinite(h) || diffusion(m2) < h * h) return persson_plastic_areas_images(p, h, m2);
  return persson_plastic_areas_fourier(p, h, m2);
}

PlasticCurve persson_plastic_curve(const SpectralMoments& moments, std::span<const Real> loads, Real h) {
  TheoryCurve curve("persson_plastic");
  const Real m2 = isotropic_m2(moments, curve.method());
  curve.check_request(loads);
  check_hardness(h, loads, curve.method());
  PlasticCurve out;
  for (const Real load : loads) {
    const PerssonPlasticAreas areas = persson_plastic_areas(load, h, m2);
    const Real total = std::min<Real>(1, areas.elastic + areas.plastic);
    curve.add(load, total);
    out.plastic_area_fraction.push_back(areas.plastic);
    // The plastic area carries H per unit area.
    out.plastic_load_fraction.push_back(areas.plastic * h / load);
  }
  out.curve = curve.finish(profile_m2_text(m2) + "; hardness H/E* = " + format_number(h) +
                           "; pressure distribution with absorbing walls at 0 and H (Persson 2001, PRL 87)");
  return out;
}

}  // namespace contactbench
