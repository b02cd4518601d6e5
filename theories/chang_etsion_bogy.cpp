#include "contactbench/theories/chang_etsion_bogy.hpp"

#include <cmath>
#include <numbers>

#include "contactbench/theories/number_text.hpp"

namespace contactbench {

Real hardness_coefficient(Real nu) {
  return 0.454 + 0.41 * nu;
}

Real critical_interference(Real radius, Real h, Real nu) {
  if (!std::isfinite(h)) return kNoHardness;
  const Real root = std::numbers::pi * hardness_coefficient(nu) * h / 2;
  return root * root * radius;
}

AsperityLaw chang_etsion_bogy_law(Real radius, Real h, Real nu) {
  const Real k = hardness_coefficient(nu), wc = critical_interference(radius, h, nu);
  AsperityLaw law;
  law.contact = [radius, h, k, wc](Real w) {
    AsperityContact c;
    if (w <= wc) {  // Hertz
      c.area = std::numbers::pi * radius * w;
      c.load = 4.0 / 3.0 * std::sqrt(radius) * w * std::sqrt(w);
    } else {  // CEB (1987): volume conserved, mean pressure K H
      c.area = std::numbers::pi * radius * w * (2 - wc / w);
      c.load = k * h * c.area;
      c.plastic_area = c.area;
      c.plastic_load = c.load;
    }
    return c;
  };
  if (std::isfinite(wc)) law.breaks = {wc};
  law.text = "Chang-Etsion-Bogy (1987): K = " + format_number(k) + ", wc = " + format_number(wc) + " m";
  return law;
}

PlasticCurve chang_etsion_bogy_curve(const SpectralMoments& moments, std::span<const Real> loads, Real h,
                                     Real nu, Real nominal_area) {
  return plastic_summits_curve("ceb", moments, loads, h, nominal_area, [h, nu](const GwParameters& gw) {
    return chang_etsion_bogy_law(gw.beta, h, nu);
  });
}

}  // namespace contactbench
