// Where a scene's heavy stages run, chosen once per command (app/cli.cpp): in this process (serial_runner)
// or on slabs of the grid across MPI ranks (app/distributed_stages.hpp, built with CB_WITH_MPI). The scene,
// its defaults and its plan are the same either way: a runner only says what it cannot run (refused in
// preflight, before any stage, naming the reason) and runs the rest.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "contactbench/app/distributions_csv.hpp"
#include "contactbench/app/scene_surface.hpp"
#include "contactbench/app/surface_source.hpp"
#include "contactbench/bem/adhesive_path.hpp"
#include "contactbench/bem/adhesive_solver.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/contact_statistics.hpp"
#include "contactbench/core/surface.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/core/topology.hpp"

namespace contactbench {

struct BemStage;
struct StageContext;

// Every load of a BEM stage on one grid: per load the solver's scalars (fields dropped) and the contact
// statistics for each connectivity asked for.
struct SolvedLoads {
  std::vector<ContactSolution> solutions;  // with an attraction: the repulsive pressure, the net load
  std::map<int, std::vector<ContactStatistics>> statistics;  // by connectivity
  std::vector<AdhesiveLoad> adhesive;                        // with an attraction, per load
  std::vector<Real> stiffness;                         // with BemStage::stiffness: K = -dP/dd [Pa/m] per load
  std::optional<MeasuredDistributions> distributions;  // with BemStage::distributions
  std::optional<AdhesivePath> approach_retract;        // with BemStage::approach_retract
  std::size_t bytes_per_rank = 0;  // the largest memory one rank held; 0 when solved by one process
};

// The surface a stage solves or sweeps: whole in this process, or on the ranks' slabs (the scene's resident
// surface, SceneSurface::resident, or a refinement of it, refine_on_slabs), of which this process has the
// grid only.
struct StageSurface {
  Grid grid;                       // as solved: its periodicity the stage's boundary
  const Surface* whole = nullptr;  // null: slabs on the ranks (a distributed runner's only), which ones below
  // Bytes of whole-surface heights this process holds while the stage runs (the scene's, and the stage's
  // refined or re-flagged copy): what a distributed runner adds to rank 0's memory.
  std::size_t root_bytes = 0;
  // With `whole` null: the slabs of the last refine_on_slabs (true) or the scene's resident slabs (false).
  bool refined_slabs = false;
};

class StageRunner {
 public:
  virtual ~StageRunner() = default;

  // Processes the stages run on (1: this one).
  virtual int ranks() const = 0;
  // Why this BEM stage cannot run here (an option with no version on this runner), or empty.
  virtual std::string bem_refusal(const BemStage& stage) const = 0;
  // The memory this machine needs for one solve of `solver` on `grid` when the runner spreads it over
  // several processes (every rank on this machine counted), with a few words on how it is spread for the
  // preflight's message; nothing when the solve is this process's alone (the method's own estimate,
  // app/methods/bem_method.cpp). `root_bytes`: what rank 0 holds whole beside its slab (the surface's
  // heights unless they stay on the slabs, fields it gathers).
  struct SpreadMemory {
    std::uintmax_t bytes = 0;
    std::string how;  // e.g. "2 ranks, 2 on this machine, about 1.2 GiB each and 256 MiB more on rank 0, ..."
  };
  virtual std::optional<SpreadMemory> bem_memory(const BemSolverOptions&, const Grid&,
                                                 std::uintmax_t /*root_bytes*/) const {
    return std::nullopt;
  }
  // The scene's generated surface made slab by slab where the stages run, reduced to what this process
  // needs (app/scene_surface.hpp); nothing when the runner makes it whole here (one process).
  virtual std::optional<ResidentSurface> make_resident_surface(const GeneratedSurfaceSpec&, int) const {
    return std::nullopt;
  }
  // The scene's file surface read by this process a bounded buffer at a time, each rank's slab sent to it as
  // it is read (app/distributed_stages.cpp); nothing when the runner is one process, or when the file's
  // format or reading options need the whole surface (core/topography_rows.hpp): then it is read whole here.
  virtual std::optional<ResidentSurface> read_resident_surface(const FileSurfaceSpec&, int) const {
    return std::nullopt;
  }
  // The scene's surface Fourier-refined to nx x ny (core/generation.hpp, refine), made slab by slab where
  // the stages run and kept there (the last such surface freed) for the stage that asked: true when the
  // runner did, and the stage then passes a StageSurface with refined_slabs; false when the runner is one
  // process, which refines here. `surface`: the scene's surface, whole in this process.
  virtual bool refine_on_slabs(const Surface& /*surface*/, Index /*nx*/, Index /*ny*/,
                               int /*threads*/) const {
    return false;
  }
  // Every load of `mean_pressures` [Pa] (ascending) on the grid of `solved`, warm-started in order; with a
  // non-empty `fields` prefix the pressure and gap of each load written as it is solved (app/stages.hpp).
  virtual SolvedLoads solve_loads(const BemStage& stage, const StageSurface& solved, Real estar,
                                  const std::vector<Real>& mean_pressures,
                                  const std::set<int>& connectivities, const std::string& fields,
                                  const StageContext& context) const = 0;
  virtual SweepCurve sweep(const StageSurface& surface, const SweepLevels& levels, const Topology& topology,
                           int threads) const = 0;
};

// This process: what a command runs on unless started as several MPI ranks.
const StageRunner& serial_runner();

}  // namespace contactbench
