// Elastic-plastic summits on Greenwood-Williamson statistics (docs/theory.md section 11.1): the GW summits
// with McCool's parameters (theories/greenwood_williamson.hpp), each deforming by a single-asperity law of
// its interference w = z - d instead of Hertz's. With the summit height s = (z - ys)/sigma_s Gaussian and t =
// (d - ys)/sigma_s,
//   A/A0 = eta int_0^inf A1(u sigma_s) phi(t + u) du,   P/A0 = eta int_0^inf P1(u sigma_s) phi(t + u) du,
// and the same for the plastic area and load. The laws: Chang-Etsion-Bogy (theories/chang_etsion_bogy.hpp)
// and Kogut-Etsion (theories/kogut_etsion.hpp); Hertz without a hardness, which is GW.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "contactbench/core/spectrum.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"
#include "contactbench/theories/plastic_curve.hpp"

namespace contactbench {

// One summit at interference w: its contact area [m^2], load / E* [m^2], and the part of each that is
// plastic.
struct AsperityContact {
  Real area = 0;
  Real load = 0;  // P1/E* [m^2]
  Real plastic_area = 0;
  Real plastic_load = 0;  // [m^2], as load
};

// A single-asperity law of radius R and hardness h = H/E*: the contact at interference w >= 0, and the
// interferences at which it changes regime (where the quadrature splits its panels).
struct AsperityLaw {
  std::function<AsperityContact(Real w)> contact;
  std::vector<Real> breaks;  // [m]
  std::string text;          // for the parameters, e.g. "CEB: K = 0.577, wc = 1.2e-9 m"
};

// Per unit nominal area at normalised separation t: A/A0, P/(E* A0), A_pl/A0, P_pl/(E* A0).
AsperityContact summit_sums(const GwParameters& gw, const AsperityLaw& law, Real t);

// The curve of `law` on the summits of `moments` (McCool's parameters), each load (finite, > 0, ascending,
// below h; checked with check_hardness) solved for its separation on ln P by Brent's method. A/A0 capped at
// 1, said in the parameters. make_law(gw) gives the law for the summits' radius. Spots: N/A0 x nominal_area.
PlasticCurve plastic_summits_curve(const std::string& method, const SpectralMoments& moments,
                                   std::span<const Real> loads, Real h, Real nominal_area,
                                   const std::function<AsperityLaw(const GwParameters&)>& make_law);

}  // namespace contactbench
