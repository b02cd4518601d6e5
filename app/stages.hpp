// The stages a scene's methods can need (docs/architecture.md, data flow), each identified by what it
// computes so that methods asking for the same one share it: a sweep of one topology at one set of levels,
// and a load-stepped BEM solve of one grid, boundary and solver setting. What each leaves for the methods is
// its products. Running them reports through the run's observer (app/run_observer.hpp) and nothing else.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "contactbench/app/distributions_csv.hpp"
#include "contactbench/app/methods/bem_settings.hpp"
#include "contactbench/app/run_observer.hpp"
#include "contactbench/app/scene_surface.hpp"
#include "contactbench/bem/adhesive_path.hpp"
#include "contactbench/bem/adhesive_solver.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/contact_statistics.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/surface.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/core/topology.hpp"

namespace contactbench {

struct SweepStage {
  Topology topology;
  SweepLevels levels;
  Index refine = 0;          // points a side after Fourier refinement; 0 = the scene's surface as it is
  std::string name() const;  // e.g. "sweep (exact levels, 4-connectivity, periodic in x and y)"
  bool same_as(const SweepStage& other) const;
};

struct SweepProducts {
  SweepCurve sweep;     // A_c(z), N(z) at the stage's levels
  LoadAreaCurve model;  // the plateau model of the sweep (theories/plateau_model.hpp), at the sweep's levels
  double seconds = 0;   // refinement + sweep + model
};

// One BEM solve of every scene load, warm-started in increasing order: the solve settings of the BEM
// method (app/methods/bem_settings.hpp; its method-only settings, e.g. the spot connectivity, left at their
// defaults, since labelling is not part of the solve and methods differing only there share it), the
// boundary resolved against the surface, and the interface's hardness as the method runs it.
struct BemStage {
  BemSettings settings;  // settings.mirrored resolved (resolve_boundary)
  bool periodic = true;
  // An unset boundary on a non-periodic problem solved as is: why (resolve_boundary); printed by name().
  std::string as_is_because;
  std::optional<Real> hardness;         // [Pa]: perfectly plastic pressure cap; absent = purely elastic
  std::optional<AdhesionLaw> adhesion;  // absent: non-adhesive (bem/adhesive_solver.hpp)
  // The scene's load path (loads.path = "as listed"), P/(E* A0) in the order solved; empty: the scene's loads
  // ascending. With a hardness the surface keeps its plastic deformation along it
  // (BemSolverOptions::keep_plastic_deformation; docs/solvers.md "Hardness").
  std::vector<Real> load_path;
  // The contact stiffness of each converged state (bem/contact_stiffness.hpp): only when the scene compares
  // it (Scene::compare), an extra linear solve per load.
  bool stiffness = false;
  // The scene's `distributions`: at this load (P/(E* A0)) the histograms of pressure and gap and the cluster
  // sizes (app/distributions_csv.hpp) are measured from the fields before they are dropped. Absent: none.
  std::optional<DistributionsSpec> distributions;
  // The scene's `approach_retract` path, run after the loads by an adhesive stage; absent: none.
  std::optional<AdhesivePathOptions> approach_retract;
  std::string name() const;  // e.g. "bem (active_set, periodic, tolerance 1e-08)"
  // Which of the mean pressures [Pa] the distributions are measured at: the first at their load (times E*),
  // along a path too; none without distributions or when no solve is at that load. Both runners use it.
  std::optional<std::size_t> distributions_solve(const std::vector<Real>& mean_pressures, Real estar) const;
  // Methods that ask for equal solves share one.
  bool operator==(const BemStage& other) const;
};

// Per load, the solver's scalars and the contact statistics for each connectivity asked for.
struct BemProducts {
  std::vector<ContactSolution> solutions;  // fields dropped (pressure and gap emptied) to keep memory small
  std::map<int, std::vector<ContactStatistics>> statistics;  // by connectivity
  double seconds = 0;                                        // refinement + solves + statistics
  Index points = 0;                                          // nodes of the grid solved on
  bool periodic = true;                                      // the boundary solved
  bool mirrored = false;      // non-periodic, solved as its mirrored extension (BemStage::settings.mirrored)
  std::string as_is_because;  // BemStage::as_is_because
  std::optional<Real> hardness;         // the cap solved with [Pa]; none: elastic
  std::optional<AdhesionLaw> adhesion;  // the attraction solved with; none: without
  std::vector<Real>
      load_path;  // the path solved (BemStage::load_path): solutions are in its order; empty: none
  std::vector<AdhesiveLoad> adhesive;  // per load, with an attraction
  std::vector<Real> stiffness;  // K = -dP/dd [Pa/m] per load, with BemStage::stiffness; empty otherwise
  std::optional<MeasuredDistributions> distributions;  // with BemStage::distributions
  std::optional<AdhesivePath> approach_retract;        // with BemStage::approach_retract
  // With BemStage::extrapolate: the same loads solved on twice the points a side (fields dropped too).
  std::vector<ContactSolution> fine_solutions;
  std::vector<AdhesiveLoad> fine_adhesive;
  std::map<int, std::vector<ContactStatistics>> fine_statistics;  // by connectivity
  Index fine_points = 0;
  // With error_estimate = "calibrated3" or "gci3" as well: a third grid, half the first or twice the finer
  // (points a side third_nx x third_ny; bem_settings.hpp third_grid_is_coarser).
  std::vector<ContactSolution> third_solutions;
  std::map<int, std::vector<ContactStatistics>> third_statistics;  // by connectivity
  Index third_nx = 0, third_ny = 0;
  // Run on several MPI ranks (app/distributed_stages.hpp): the largest memory one rank held for a solve
  // [bytes]; 0 when solved by one process.
  std::size_t bytes_per_rank = 0;
};

class StageRunner;  // app/stage_runner.hpp

struct StageContext {
  int threads = 1;
  const RunObserver* observer = nullptr;      // may be null: quiet
  const StageRunner* stage_runner = nullptr;  // where the stages run; null: this process
  std::filesystem::path fields_folder = {};   // RunOptions::fields_folder
  const StageRunner& runner() const;
};

// The field file of load k (1-based, in the order solved): <prefix>_load<k>_<what>.txt, what = pressure |
// gap.
std::string field_path(const std::string& prefix, std::size_t k, const char* what);

// A stage on the scene's surface as it is (no refinement, no mirror) takes a resident surface's slabs where
// they are; any other gathers it whole first (SceneSurface::whole).
SweepProducts run_sweep_stage(const SweepStage& stage, const SceneSurface& surface,
                              const StageContext& context);

// `mean_pressures` [Pa] ascending; `connectivities` the spot counts the methods sharing the stage ask for.
BemProducts run_bem_stage(const BemStage& stage, const SceneSurface& surface, Real estar,
                          const std::vector<Real>& mean_pressures, const std::set<int>& connectivities,
                          const StageContext& context);

}  // namespace contactbench
