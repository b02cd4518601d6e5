#include "contactbench/theories/plateau_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/requested_loads.hpp"

namespace contactbench {

LoadAreaCurve plateau_model(const SweepCurve& sweep) {
  LoadAreaCurve curve;
  curve.method = "plateau";
  curve.parameters =
      describe(sweep.topology) + ", " +
      (sweep.levels.kind == SweepLevels::Kind::exact
           ? std::string("exact levels")
           : std::to_string(sweep.levels.count) +
                 (sweep.levels.kind == SweepLevels::Kind::paper ? " paper levels" : " uniform levels"));
  // Eq. (3) in the dimensionless form P/(E* A0) = (2/sqrt(pi)) sum sqrt(a N / A0) dz, with a = A_c/A0.
  const Real prefactor = 2 / std::sqrt(std::numbers::pi);
  Real load = 0;
  for (std::size_t j = 0; j < sweep.z.size(); ++j) {
    if (j > 0) {
      // On [z[j], z[j-1]) the contact set is the one reported at z[j] (see the header).
      const Real a_times_n = sweep.area_fraction[j] * static_cast<Real>(sweep.spots[j]);
      load += prefactor * std::sqrt(a_times_n / sweep.nominal_area) * (sweep.z[j - 1] - sweep.z[j]);
    }
    curve.separation.push_back(sweep.z[j]);
    curve.load.push_back(load);
    curve.area_fraction.push_back(sweep.area_fraction[j]);
    curve.spots.push_back(static_cast<Real>(sweep.spots[j]));
  }
  return curve;
}

LoadAreaCurve plateau_curve_at_loads(const SweepCurve& sweep, const LoadAreaCurve& model,
                                     std::span<const Real> loads) {
  validate_loads(loads, model.method);
  LoadAreaCurve curve;
  curve.method = model.method;
  curve.parameters = model.parameters;
  curve.seconds = model.seconds;
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const Real highest = model.load.empty() ? 0 : model.load.back();
  const bool reaches_lowest_height = sweep.levels.kind != SweepLevels::Kind::paper;
  for (const Real load : loads) {
    curve.load.push_back(load);
    if (load > highest) {
      if (reaches_lowest_height && !model.load.empty()) {
        // Full contact: one spot of area A0, P/(E* A0) grows by (2/sqrt(pi)) sqrt(1/A0) per unit of approach.
        const Real slope = 2 / std::sqrt(std::numbers::pi) / std::sqrt(sweep.nominal_area);
        curve.area_fraction.push_back(1);
        curve.separation.push_back(model.separation.back() - (load - highest) / slope);
        curve.spots.push_back(1);
      } else {
        curve.area_fraction.push_back(nan);
        curve.separation.push_back(nan);
        curve.spots.push_back(nan);
      }
      continue;
    }
    // The first level whose load reaches the request; j >= 1 because the first level carries no load.
    const auto j = static_cast<std::size_t>(std::lower_bound(model.load.begin(), model.load.end(), load) -
                                            model.load.begin());
    const Real step = model.load[j] - model.load[j - 1];
    const Real fraction = step > 0 ? (load - model.load[j - 1]) / step : 1;
    curve.separation.push_back(model.separation[j - 1] +
                               fraction * (model.separation[j] - model.separation[j - 1]));
    curve.area_fraction.push_back(model.area_fraction[j]);
    curve.spots.push_back(model.spots[j]);
  }
  if (!loads.empty() && loads.back() > highest)
    curve.parameters +=
        reaches_lowest_height
            ? "; full contact (A/A0 = 1) for loads above " + format_number(highest) +
                  ", the load at the lowest height"
            : "; no answer (NaN) for loads above " + format_number(highest) +
                  ", the load at the lowest level swept (the paper's levels stop at the mean plane)";
  return curve;
}

}  // namespace contactbench
