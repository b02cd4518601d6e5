#include "contactbench/app/scene_plan.hpp"

#include <algorithm>
#include <sstream>

#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

std::string describe(const SweepLevels& levels) {
  switch (levels.kind) {
    case SweepLevels::Kind::exact:
      return "exact levels";
    case SweepLevels::Kind::uniform:
      return std::to_string(levels.count) + " uniform levels";
    case SweepLevels::Kind::paper:
      return "the paper's " + std::to_string(levels.count) + " levels";
  }
  return "";
}

bool same(const SweepStage& a, const SweepStage& b) {
  return a.topology.connectivity == b.topology.connectivity && a.topology.wrap_x == b.topology.wrap_x &&
         a.topology.wrap_y == b.topology.wrap_y && a.levels.kind == b.levels.kind &&
         (a.levels.kind == SweepLevels::Kind::exact || a.levels.count == b.levels.count);
}

bool same(const BemStage& a, const BemStage& b) {
  return a.refine == b.refine && a.periodic == b.periodic && a.tolerance == b.tolerance &&
         a.max_iterations == b.max_iterations && a.hardness == b.hardness && a.solver == b.solver;
}

template <class Stage>
int index_of(std::vector<Stage>& stages, const Stage& stage) {
  const auto found =
      std::find_if(stages.begin(), stages.end(), [&](const Stage& s) { return same(s, stage); });
  if (found != stages.end()) return static_cast<int>(found - stages.begin());
  stages.push_back(stage);
  return static_cast<int>(stages.size() - 1);
}

}  // namespace

std::string SweepStage::name() const {
  return "sweep (" + describe(levels) + ", " + describe(topology) + ")";
}

std::string BemStage::name() const {
  std::ostringstream text;
  text << "bem (";
  if (refine > 0) text << "refined to " << refine << " x " << refine << ", ";
  text << solver_name(solver) << ", " << (periodic ? "periodic" : "non-periodic") << ", tolerance "
       << tolerance;
  if (hardness) text << ", hardness " << *hardness << " Pa";
  text << ")";
  return text.str();
}

bool ScenePlan::needs_theories() const {
  return std::find(stage_of_method.begin(), stage_of_method.end(), -1) != stage_of_method.end();
}

bool is_periodic(const SurfaceSpec& surface) {
  if (const auto* file = std::get_if<FileSurfaceSpec>(&surface.source)) return file->periodic;
  return true;  // the generator makes periodic surfaces
}

ScenePlan plan_scene(const Scene& scene) {
  ScenePlan plan;
  plan.surface_periodic = is_periodic(scene.surface);
  for (const MethodSpec& method : scene.methods) {
    int stage = -1;
    if (const auto* plateau = std::get_if<PlateauMethodSpec>(&method.options)) {
      const bool periodic = plateau->periodic.value_or(plan.surface_periodic);
      const Connectivity connectivity = plateau->connectivity == 8 ? Connectivity::eight : Connectivity::four;
      stage =
          index_of(plan.sweeps, SweepStage{Topology::for_surface(connectivity, periodic), plateau->levels});
    } else if (const auto* bem = std::get_if<BemMethodSpec>(&method.options)) {
      if (bem->refine > 0 && !plan.surface_periodic)
        throw Error("methods." + method.label +
                    ".refine: Fourier refinement needs a periodic surface, and this scene's surface is not "
                    "periodic; accepted: refine = 0 (solve on the file's own grid)");
      stage = index_of(plan.bems, BemStage{.refine = bem->refine,
                                           .periodic = bem->periodic.value_or(plan.surface_periodic),
                                           .tolerance = bem->tolerance,
                                           .max_iterations = bem->max_iterations,
                                           .hardness = bem->hardness,
                                           .solver = bem->solver});
    }
    plan.stage_of_method.push_back(stage);
  }
  return plan;
}

}  // namespace contactbench
