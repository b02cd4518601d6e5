#include "contactbench/theories/majumdar_bhushan.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/theories/brent_root.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/theory_curve.hpp"

namespace contactbench {
namespace {

constexpr Real kGamma = 1.5;  // MB's frequency ratio of the W-M series

// (x^e - y^e)/e, continuous through e = 0 (where it is ln(x/y)).
Real power_difference(Real x, Real y, Real e) {
  if (std::abs(e) < 1e-12) return std::log(x / y);
  return std::pow(y, e) * std::expm1(e * std::log(x / y)) / e;
}

}  // namespace

FractalParameters fit_fractal_parameters(const Surface& surface) {
  const FourierCoefficients c = fourier_coefficients(surface);
  const SampledPsd x = profile_psd_x(c), y = profile_psd_y(c);
  const Real q_max = std::min(x.q.back(), y.q.back());
  Real n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const SampledPsd* psd : {&x, &y})
    for (std::size_t k = 0; k < psd->q.size(); ++k) {
      const Real q = psd->q[k];
      if (!(q >= q_max / 30 && q <= q_max / 4) || !(psd->c[k] > 0)) continue;
      const Real lf = std::log(q / (2 * pi)), ls = std::log(4 * pi * psd->c[k]);
      n += 1;
      sx += lf;
      sy += ls;
      sxx += lf * lf;
      sxy += lf * ls;
    }
  if (n < 3)
    throw Error("majumdar_bhushan: too few wavevectors to fit a power law (" + format_number(n) + ")");
  const Real slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), intercept = (sy - slope * sx) / n;
  FractalParameters f;
  f.dimension = (5 + slope) / 2;  // S ~ f^-(5-2D)
  if (!(f.dimension > 1 && f.dimension < 2))
    throw Error("majumdar_bhushan: the profile spectrum's slope " + format_number(slope) +
                " gives D = " + format_number(f.dimension) + ", outside MB's range 1 < D < 2");
  f.roughness = std::exp((std::log(2 * std::log(kGamma)) + intercept) / (2 * (f.dimension - 1)));
  return f;
}

FractalContact majumdar_bhushan_contact(const FractalParameters& fr, Real h, Real largest,
                                        Real nominal_area) {
  const Real d = fr.dimension, g = fr.roughness;
  const Real critical = std::isfinite(h) ? g * g / std::pow(h / 2, 2 / (d - 1)) : 0;
  const Real spots = d / 2 * std::pow(largest, d / 2);  // n(a) = spots a^-(D/2 + 1)
  FractalContact c;
  c.area = d / (2 - d) * largest / nominal_area;
  const Real split = std::min(critical, largest);  // spots below `split` are plastic
  // int_0^split H a n(a) da = H spots split^(1-D/2)/(1-D/2)
  c.plastic_area = split > 0 ? spots * std::pow(split, 1 - d / 2) / (1 - d / 2) / nominal_area : 0;
  c.plastic_load = std::isfinite(h) ? h * c.plastic_area : 0;
  if (largest > critical) {
    // int_split^aL (4 sqrt(pi)/3) G^(D-1) a^((3-D)/2) n(a) da
    const Real e = (3 - 2 * d) / 2;
    const Real integral = critical > 0 ? power_difference(largest, critical, e) : std::pow(largest, e) / e;
    c.elastic_load = 4 * std::sqrt(pi) / 3 * std::pow(g, d - 1) * spots * integral / nominal_area;
  }
  return c;
}

PlasticCurve majumdar_bhushan_curve(const FractalParameters& fr, std::span<const Real> loads, Real h,
                                    Real nominal_area) {
  TheoryCurve curve("majumdar_bhushan");
  curve.check_request(loads, nominal_area);
  check_hardness(h, loads, curve.method());
  if (!std::isfinite(h) && fr.dimension >= 1.5)
    throw Error(
        "majumdar_bhushan: without a hardness the elastic load of the small spots diverges for D >= 1.5 (D "
        "= " +
        format_number(fr.dimension) + "); the model needs interface.hardness");
  auto log_load = [&](Real log_largest) {
    const FractalContact c = majumdar_bhushan_contact(fr, h, std::exp(log_largest), nominal_area);
    return std::log(c.elastic_load + c.plastic_load);
  };
  // The largest spot from 1e-30 A0 to the A0 (2-D)/D at which A = A0.
  const Real low = std::log(1e-30 * nominal_area),
             high = std::log(nominal_area * (2 - fr.dimension) / fr.dimension);
  PlasticCurve out;
  for (const Real load : loads) {
    const Real target = std::log(load), f_low = log_load(low) - target, f_high = log_load(high) - target;
    if (f_high < 0)
      throw Error("majumdar_bhushan: the load P/(E* A0) = " + format_number(load) +
                  " is beyond the load at full contact, " + format_number(std::exp(f_high + target)));
    if (f_low > 0)
      throw Error("majumdar_bhushan: the load P/(E* A0) = " + format_number(load) +
                  " is below the smallest load solved for");
    const Real x = find_root([&](Real v) { return log_load(v) - target; }, low, high, f_low, f_high,
                             kLogLoadTolerance, 1e-15);
    const FractalContact c = majumdar_bhushan_contact(fr, h, std::exp(x), nominal_area);
    const Real total = c.elastic_load + c.plastic_load;
    curve.add(total, std::min<Real>(c.area, 1));
    out.plastic_area_fraction.push_back(std::min<Real>(c.plastic_area, 1));
    out.plastic_load_fraction.push_back(c.plastic_load / total);
  }
  const Real critical =
      std::isfinite(h) ? fr.roughness * fr.roughness / std::pow(h / 2, 2 / (fr.dimension - 1)) : 0;
  out.curve = curve.finish("Majumdar-Bhushan (1991): D = " + format_number(fr.dimension) +
                           ", G = " + format_number(fr.roughness) +
                           " m (fitted to the profile spectrum over q in [q_max/30, q_max/4]), "
                           "critical spot area ac = " +
                           format_number(critical) + " m^2, H/E* = " + format_number(h));
  return out;
}

}  // namespace contactbench
