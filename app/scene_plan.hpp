// The planner (docs/architecture.md, data flow): from a scene's methods, the stages that must run, each
// once: the union of every method's needs (app/methods/method.hpp). Analytic theories need the spectral
// moments only; the plateau model one sweep per (topology, levels); the BEM one load-stepped solve per
// (grid, boundary, solver options), labelled once for every connectivity its methods count spots with.
// Nothing else runs: a scene of theories never sorts a height nor solves a contact, and an effect that no
// method asks for (a pressure cap, a refined grid) is not in the plan.
#pragma once

#include <set>
#include <vector>

#include "contactbench/app/methods/method.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/stages.hpp"
#include "contactbench/core/grid.hpp"

namespace contactbench {

struct PlannedBem {
  BemStage stage;
  std::set<int> connectivities;  // of the methods that share it
};

struct ScenePlan {
  SceneContext context;  // what the scene's surface is (periodic, points a side when known)
  // The moments: needed by the theories, and always by the report (its areal kappa reads gbar).
  bool moments = true;
  std::vector<SweepStage> sweeps;
  std::vector<PlannedBem> bems;
  struct Stages {
    int sweep = -1;  // index into sweeps, -1: none
    int bem = -1;    // index into bems, -1: none
  };
  std::vector<Stages> of_method;  // for each method of the scene, in its order
};

// The context one method runs in: the scene's, with the interface's effects less those it ignores.
SceneContext method_context(const SceneContext& scene_context, const Scene& scene, const MethodSpec& method);

// Pure: reads the methods' needs for the scene's surface (made already: its grid says whether it is
// periodic), runs nothing, refuses nothing (the preflight does, app/scene_run.hpp). The plan is the same on
// one process and on MPI ranks, where a stage the ranks cannot run is refused by name.
ScenePlan plan_scene(const Scene& scene, const Grid& surface);

}  // namespace contactbench
