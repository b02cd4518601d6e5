#include "contactbench/app/scene_plan.hpp"

#include <algorithm>

namespace contactbench {

namespace {

template <class Stage, class Same>
int index_of(std::vector<Stage>& stages, const Stage& stage, Same same) {
  const auto found =
      std::find_if(stages.begin(), stages.end(), [&](const Stage& s) { return same(s, stage); });
  if (found != stages.end()) return static_cast<int>(found - stages.begin());
  stages.push_back(stage);
  return static_cast<int>(stages.size() - 1);
}

}  // namespace

SceneContext method_context(const SceneContext& scene_context, const Scene& scene, const MethodSpec& method) {
  SceneContext context = scene_context;
  context.interface = scene.interface.without(method.ignored);
  return context;
}

ScenePlan plan_scene(const Scene& scene, const Grid& surface) {
  ScenePlan plan;
  plan.context = {
      .surface_points = surface.nx, .surface_periodic = surface.periodic, .load_path = scene.load_path};
  for (const MethodSpec& method : scene.methods) {
    const MethodNeeds needs = method.method->needs(method_context(plan.context, scene, method));
    ScenePlan::Stages stages;
    if (needs.sweep)
      stages.sweep = index_of(plan.sweeps, *needs.sweep,
                              [](const SweepStage& a, const SweepStage& b) { return a.same_as(b); });
    if (needs.bem) {
      // The stiffness of each state when the scene compares it (none with an attraction, whose change under
      // an approach the linearised response leaves out: docs/theory.md section 12.2).
      BemStage stage = *needs.bem;
      stage.stiffness = scene.compares(Quantity::stiffness) && !stage.adhesion;
      stage.distributions = scene.distributions;  // measured at one load only when the scene asks
      if (stage.adhesion) stage.approach_retract = scene.approach_retract;  // an adhesive stage's path
      stages.bem = index_of(plan.bems, PlannedBem{stage, {}},
                            [](const PlannedBem& a, const PlannedBem& b) { return a.stage == b.stage; });
      PlannedBem& planned = plan.bems[static_cast<std::size_t>(stages.bem)];
      planned.connectivities.insert(needs.bem_connectivity);
      // A declared "as_is" and an unset boundary that fell back to it are one solve; the shared stage keeps
      // the fallback's reason, which the unset method's parameters print (the declared one's do not).
      if (planned.stage.as_is_because.empty()) planned.stage.as_is_because = stage.as_is_because;
    }
    plan.of_method.push_back(stages);
  }
  return plan;
}

}  // namespace contactbench
