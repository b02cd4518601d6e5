#include "contactbench/theories/plateau_at_load.hpp"

#include <cmath>

#include "contactbench/core/error.hpp"
#include "contactbench/core/labelling.hpp"
#include "contactbench/theories/plateau_hertz.hpp"
#include "contactbench/theories/plateau_model.hpp"

namespace contactbench {

PlateauAtLoad plateau_at_load(const Surface& surface, const SweepCurve& levels, const LoadAreaCurve& model,
                              const Topology& topology, Real load, PlateauReading reading) {
  // With exact levels the model's curve at the load is exact (no interpolation between levels).
  const std::vector<Real> loads{load};
  const LoadAreaCurve at = reading == PlateauReading::paper
                               ? plateau_curve_at_loads(levels, model, loads)
                               : plateau_hertz_curve_at_loads(levels, model, loads);
  if (!std::isfinite(at.separation.front()))
    throw Error("the " + at.method + " model gives no cut level at the load " + std::to_string(load) + " (" +
                at.parameters + ")");

  PlateauAtLoad result;
  result.level = at.separation.front();
  result.area_fraction = at.area_fraction.front();
  const HeightMap& h = surface.heights();
  result.points = h.size();
  for (Index i = 0; i < h.size(); ++i)
    if (h.data()[i] <= result.level) result.gaps.push_back(result.level - h.data()[i]);
  const Real share = reading == PlateauReading::paper ? 1.0 : 0.5;  // a = r_b/sqrt(2): half the disc
  for (const Index a : label_components(threshold_above(h, result.level), topology).areas)
    result.spot_areas.push_back(share * static_cast<Real>(a));
  return result;
}

}  // namespace contactbench
