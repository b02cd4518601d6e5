#include "contactbench/theories/adhesive_plateaus.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/theory_curve.hpp"

namespace contactbench {

LoadAreaCurve adhesive_plateau_curve_at_loads(const SweepCurve& sweep, const LoadAreaCurve& model, Real estar,
                                              Real work, AdhesivePlateauSpot spot,
                                              std::span<const Real> loads) {
  const bool punch = spot == AdhesivePlateauSpot::kendall_punch;
  TheoryCurve curve(punch ? "plateau_kendall" : "plateau_hertz_jkr");
  curve.check_request(loads);
  if (!(std::isfinite(work) && work > 0))
    throw Error(curve.method() + ": the work of adhesion must be finite and > 0 J/m^2, got " +
                format_number(work));
  if (!(std::isfinite(estar) && estar > 0))
    throw Error(curve.method() + ": E* must be finite and > 0 Pa, got " + format_number(estar));
  const std::size_t levels = sweep.z.size();
  if (model.load.size() != levels) throw Error(curve.method() + ": the model is not the sweep's");
  const Real a0 = sweep.nominal_area;
  // Per level: the adhesive load (punches or Hertz-consistent tips), its area, spots and separation.
  std::vector<Real> load(levels), area(levels);
  for (std::size_t j = 0; j < levels; ++j) {
    const Real n = static_cast<Real>(sweep.spots[j]);
    const Real bearing = n > 0 ? std::sqrt(sweep.area_fraction[j] * a0 / (std::numbers::pi * n)) : 0;
    const Real radius = punch ? bearing : bearing / std::numbers::sqrt2;
    const Real pull = n * std::sqrt(8 * std::numbers::pi * work * radius * radius * radius / estar) / a0;
    load[j] = (punch ? model.load[j] : model.load[j] / std::numbers::sqrt2) - pull;
    area[j] = punch ? sweep.area_fraction[j] : sweep.area_fraction[j] / 2;
  }
  Real beyond = std::numeric_limits<Real>::quiet_NaN();
  std::size_t j = 0;
  for (const Real request : loads) {
    while (j < levels && load[j] < request)
      ++j;
    if (j == levels) {
      if (std::isnan(beyond)) beyond = request;
      curve.add(request, std::numeric_limits<Real>::quiet_NaN());
      continue;
    }
    // Inside level j's interval the load is linear in z from load[j] − (P[j] − P[j−1]) (scaled) up to
    // load[j].
    const Real scale = punch ? 1 : 1 / std::numbers::sqrt2;
    const Real low = j > 0 ? load[j] - scale * (model.load[j] - model.load[j - 1]) : load[j];
    Real z = sweep.z[j];
    if (j > 0 && request > low && load[j] > low)
      z = sweep.z[j] + (sweep.z[j - 1] - sweep.z[j]) * (load[j] - request) / (load[j] - low);
    curve.add(request, area[j], z, static_cast<Real>(sweep.spots[j]));
  }
  std::string parameters =
      std::string(punch ? "the paper's plateaus as adhesive flat punches (Kendall 1971)"
                        : "the Hertz-consistent plateaus as JKR contacts (Johnson, Kendall & Roberts 1971)") +
      ", the project's adhesive reading, not the paper's: each spot's load less sqrt(8 pi w E* a^3), w = " +
      format_number(work) + " J/m^2 (used alone), E* = " + format_number(estar) +
      " Pa; approach path: a load takes the first level from the top whose adhesive load reaches it";
  if (!std::isnan(beyond))
    parameters += "; loads from " + format_number(beyond) + " are beyond the sweep's last level (NaN)";
  return curve.finish(std::move(parameters));
}

}  // namespace contactbench
