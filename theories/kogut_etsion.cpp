#include "contactbench/theories/kogut_etsion.hpp"

#include <cmath>
#include <numbers>

#include "contactbench/theories/chang_etsion_bogy.hpp"
#include "contactbench/theories/number_text.hpp"

namespace contactbench {

AsperityLaw kogut_etsion_law(Real radius, Real h, Real nu) {
  const Real wc = critical_interference(radius, h, nu);
  const Real pc = 4.0 / 3.0 * std::sqrt(radius) * wc * std::sqrt(wc), ac = std::numbers::pi * radius * wc;
  AsperityLaw law;
  law.contact = [radius, h, wc, pc, ac](Real w) {
    AsperityContact c;
    const Real x = w / wc;
    if (!(x > 1)) {  // Hertz (also without a hardness: wc infinite, x = 0)
      c.area = std::numbers::pi * radius * w;
      c.load = 4.0 / 3.0 * std::sqrt(radius) * w * std::sqrt(w);
    } else if (x <= 6) {  // Kogut-Etsion (2002), first elastic-plastic regime
      c.area = 0.93 * ac * std::pow(x, 1.136);
      c.load = 1.03 * pc * std::pow(x, 1.425);
    } else if (x <= 110) {  // second elastic-plastic regime
      c.area = 0.94 * ac * std::pow(x, 1.146);
      c.load = 1.40 * pc * std::pow(x, 1.263);
      c.plastic_area = c.area;
      c.plastic_load = c.load;
    } else {  // fully plastic: the truncated sphere at mean pressure H
      c.area = 2 * std::numbers::pi * radius * w;
      c.load = h * c.area;
      c.plastic_area = c.area;
      c.plastic_load = c.load;
    }
    return c;
  };
  if (std::isfinite(wc)) law.breaks = {wc, 6 * wc, 110 * wc};
  law.text = "Kogut-Etsion (2002) fits: K = " + format_number(hardness_coefficient(nu)) +
             ", wc = " + format_number(wc) + " m";
  return law;
}

PlasticCurve kogut_etsion_curve(const SpectralMoments& moments, std::span<const Real> loads, Real h, Real nu,
                                Real nominal_area) {
  return plastic_summits_curve("kogut_etsion", moments, loads, h, nominal_area,
                               [h, nu](const GwParameters& gw) { return kogut_etsion_law(gw.beta, h, nu); });
}

}  // namespace contactbench
