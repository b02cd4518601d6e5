// Running a scene: make the surface, run each planned stage once (app/scene_plan.hpp), and turn the stages'
// products into one load-area curve per method at the scene's loads, each with the wall time it cost.
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_plan.hpp"
#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench {

struct StageRecord {
  std::string name;
  double seconds = 0;
};

struct MethodResult {
  std::string label;
  MethodKind kind = MethodKind::bem;
  // At the scene's loads. For the BEM, area_fraction is the perimeter-corrected area (docs/theory.md section
  // 6): the best estimate of the real area a grid gives; the node count is the column area_fraction_nodes.
  LoadAreaCurve curve;
  // The method's own columns beside load, area_fraction, separation and spots (e.g. iterations for the BEM).
  std::vector<std::pair<std::string, std::vector<Real>>> columns;
  // Wall time of the stages the method needed (shared stages are charged in full to each method that needs
  // them) plus its own evaluation; making the scene's surface is charged to no method.
  double seconds = 0;
};

struct SceneReport {
  Scene scene;
  Grid grid;                          // of the scene's surface (before any refinement a method asks for)
  SpectralMoments moments;            // of the scene's surface (profile moments, docs/theory.md section 1)
  std::vector<StageRecord> stages;    // every stage that ran, in order
  std::vector<MethodResult> methods;  // in the scene's order
  int threads = 1;
  double seconds = 0;  // the whole run
};

struct RunOptions {
  int threads = 1;
  std::ostream* progress = nullptr;  // progress of long stages (stderr for the CLI); null: quiet
};

SceneReport run_scene(const Scene& scene, const RunOptions& options);

}  // namespace contactbench
