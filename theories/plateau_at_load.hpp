// The plateau models at one load (docs/theory.md section 12.8): the cut level z at which the multi-plateaus
// model (theories/plateau_model.hpp) or its Hertz-consistent variant (theories/plateau_hertz.hpp, the
// project's own) carries the load, the gaps z - h of the undeformed surface outside its spots, and the areas
// of its spots. What the distributions of a scene's reference load set beside the BEM's histograms.
#pragma once

#include <vector>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/surface.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/core/topology.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/theories/plateau_reading.hpp"

namespace contactbench {

struct PlateauAtLoad {
  Real level = 0;                // the cut level z [m] at the load (exact levels, plateau_curve_at_loads)
  Real area_fraction = 0;        // the model's A/A0
  std::vector<Real> gaps;        // z - h [m] at every node with h <= z (the rest is in the spots, gap 0)
  std::vector<Real> spot_areas;  // in nodes: the clusters of {h > z}; halved for the Hertz reading
  Index points = 0;              // nodes of the surface
};

// On `surface` with `topology` (the spots' connectivity and periodicity), at load = P/(E* A0) > 0, from the
// surface's exact sweep `levels` (SweepLevels::exact(), the same topology) and model = plateau_model(levels).
// Throws Error when the model gives no answer there (the Hertz reading at full contact).
PlateauAtLoad plateau_at_load(const Surface& surface, const SweepCurve& levels, const LoadAreaCurve& model,
                              const Topology& topology, Real load, PlateauReading reading);

}  // namespace contactbench
