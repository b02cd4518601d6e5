#include "contactbench/theories/plateau_capped.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/requested_loads.hpp"

namespace contactbench {

PlasticCurve plateau_capped_curve_at_loads(const SweepCurve& sweep, const LoadAreaCurve& model,
                                           std::span<const Real> loads, Real h, PlateauReading reading) {
  const bool hertz = reading == PlateauReading::hertz;
  const std::string method = hertz ? "plateau_hertz_capped" : "plateau_capped";
  validate_loads(loads, method);
  check_hardness(h, loads, method);
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  // The elastic load of the reading at each level: the paper's, or the Hertz-consistent one (section 8.3).
  const Real elastic_scale = hertz ? 1 / std::numbers::sqrt2 : 1;
  const std::size_t levels = model.load.size();
  // The capped load at each level (docs/theory.md section 11.2): P_j = E_j + M_j, M_j = min(M_{j-1}, C_j -
  // E_j), M_0 = 0; and before_cap_j = E_j + M_{j-1}, the load the elastic branch would reach at level j.
  std::vector<Real> capped(levels), offset_before(levels);
  std::vector<bool> reaches_cap(levels, false);  // the step down to level j ends on the ceiling
  Real offset = 0;  // M: how far plastic flow has lowered the load below the elastic one (<= 0)
  for (std::size_t j = 0; j < levels; ++j) {
    const Real elastic = elastic_scale * model.load[j];
    const Real ceiling = h * model.area_fraction[j];
    offset_before[j] = offset;
    reaches_cap[j] = elastic + offset >= ceiling;
    if (std::isfinite(ceiling)) offset = std::min(offset, ceiling - elastic);
    capped[j] = elastic + offset;
  }

  PlasticCurve out;
  LoadAreaCurve& curve = out.curve;
  curve.method = method;
  curve.parameters =
      model.parameters + "; yield limit H/E* = " + format_number(h) +
      (hertz ? ": Hertz-consistent plateaus (this project), area max(A_c/2, P/H) with the load "
               "capped at H A_c"
             : ": the paper's plateaus with the load capped at H A_c (this project)");
  curve.seconds = model.seconds;
  const Real highest = levels == 0 ? 0 : capped.back();
  const bool reaches_lowest_height = sweep.levels.kind != SweepLevels::Kind::paper;
  bool beyond = false;
  for (const Real load : loads) {
    curve.load.push_back(load);
    if (levels == 0 || load > highest) {
      beyond = true;
      // Full contact below the lowest height: one spot of area A0, elastic (the ceiling H A0 exceeds every
      // accepted load); the Hertz reading has no paraboloid there (as plateau_hertz).
      if (reaches_lowest_height && levels > 0 && !hertz) {
        const Real slope = 2 / std::sqrt(std::numbers::pi) / std::sqrt(sweep.nominal_area);
        curve.area_fraction.push_back(1);
        curve.separation.push_back(model.separation.back() - (load - highest) / slope);
        curve.spots.push_back(1);
      } else {
        curve.area_fraction.push_back(nan);
        curve.separation.push_back(nan);
        curve.spots.push_back(nan);
      }
      out.plastic_area_fraction.push_back(curve.area_fraction.back() == 1 ? 0 : nan);
      out.plastic_load_fraction.push_back(curve.area_fraction.back() == 1 ? 0 : nan);
      continue;
    }
    // The first level whose capped load reaches the request (capped is non-decreasing; level 0 carries 0).
    const auto j =
        static_cast<std::size_t>(std::lower_bound(capped.begin(), capped.end(), load) - capped.begin());
    const Real bearing = model.area_fraction[j];
    // On the elastic branch of the step the load is E(z) + M_{j-1}, E linear in z between the levels.
    const Real e0 = elastic_scale * model.load[j - 1], e1 = elastic_scale * model.load[j];
    const Real fraction =
        e1 > e0 ? std::clamp((load - offset_before[j] - e0) / (e1 - e0), Real{0}, Real{1}) : 1;
    curve.separation.push_back(model.separation[j - 1] +
                               fraction * (model.separation[j] - model.separation[j - 1]));
    curve.spots.push_back(model.spots[j]);
    Real area = 0;
    bool plastic = false;
    if (hertz) {
      area = std::max(bearing / 2, load / h);
      plastic = load / h > bearing / 2;
    } else {
      area = bearing;
      // The step ends on the cap: the plateaus' mean pressure lies between H A_{j-1}/A_j and H, and they
      // yield within the step (docs/theory.md section 11.2).
      plastic = reaches_cap[j];
    }
    curve.area_fraction.push_back(area);
    out.plastic_area_fraction.push_back(plastic ? area : 0);
    out.plastic_load_fraction.push_back(plastic ? 1 : 0);
  }
  if (beyond)
    curve.parameters += reaches_lowest_height && !hertz
                            ? "; full elastic contact (A/A0 = 1) for loads above " + format_number(highest)
                            : "; no answer (NaN) for loads above " + format_number(highest);
  return out;
}

}  // namespace contactbench
