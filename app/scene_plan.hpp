// The planner (docs/architecture.md, data flow): from a scene's methods, the stages that must run, each once.
// Analytic theories need the spectral moments only; the plateau model one sweep per (topology, levels);
// the BEM one load-stepped solve per (grid, boundary, solver options). Nothing else runs: a scene of theories
// never sorts a height nor solves a contact, a scene without the BEM never runs it, and an effect that no
// method asks for (a pressure cap, a refined grid) is not in the plan.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contactbench/app/scene.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/topology.hpp"

namespace contactbench {

struct SweepStage {
  Topology topology;
  SweepLevels levels;
  std::string name() const;  // e.g. "sweep (exact levels, 4-connectivity, periodic in x and y)"
};

// One BEM solve of every scene load, warm-started in increasing order. Methods that differ only in the
// connectivity of their spot count share it (labelling the contact map is not part of the solve).
struct BemStage {
  Index refine = 0;  // points a side after Fourier refinement; 0 = the scene's surface as it is
  bool periodic = true;
  Real tolerance = 0;
  Index max_iterations = 0;
  std::optional<Real> hardness;
  SolverKind solver = kDefaultSolver;
  std::string name() const;  // e.g. "bem (512 x 512, periodic, tolerance 1e-08)"
};

struct ScenePlan {
  bool surface_periodic = true;  // what the scene's surface is: generated surfaces are periodic
  std::vector<SweepStage> sweeps;
  std::vector<BemStage> bems;
  // For each method of the scene (same order): the index of its sweep or BEM stage, -1 for the theories.
  std::vector<int> stage_of_method;
  bool needs_theories() const;
};

// Refuses (Error naming the method's key) what cannot be planned: a refinement of a non-periodic surface.
ScenePlan plan_scene(const Scene& scene);

bool is_periodic(const SurfaceSpec& surface);

}  // namespace contactbench
