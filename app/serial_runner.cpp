// The stages in this process (app/stage_runner.hpp): every BEM option and the sweep as the libraries have
// them, nothing refused.
#include <chrono>
#include <cmath>
#include <optional>

#include "contactbench/app/distributions_csv.hpp"
#include "contactbench/app/load_fields.hpp"
#include "contactbench/app/mirrored_boundary.hpp"
#include "contactbench/app/stage_runner.hpp"
#include "contactbench/app/stages.hpp"
#include "contactbench/bem/contact_stiffness.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/labelling.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

using Clock = std::chrono::steady_clock;

class SerialRunner final : public StageRunner {
  // One process makes no resident surface (make_resident_surface), so every stage's surface is whole here.
  static const Surface& whole(const StageSurface& surface) {
    if (!surface.whole) throw Error("internal: a stage of one process was given no heights");
    return *surface.whole;
  }

 public:
  int ranks() const override { return 1; }
  std::string bem_refusal(const BemStage&) const override { return ""; }

  SolvedLoads solve_loads(const BemStage& stage, const StageSurface& given, Real estar,
                          const std::vector<Real>& mean_pressures, const std::set<int>& connectivities,
                          const std::string& fields, const StageContext& context) const override {
    // boundary = "mirrored": the solver sees the patch's periodic even extension (app/mirrored_boundary.hpp);
    // everything after the solve is taken on the patch, the extension's first quarter.
    const bool mirrored = stage.settings.mirrored.value_or(false);
    const Grid& judged = given.grid;
    const std::optional<Surface> extension =
        mirrored ? std::optional<Surface>(mirrored_surface(whole(given))) : std::nullopt;
    const Surface& solved = extension ? *extension : whole(given);
    const auto start = Clock::now();
    const RunObserver quiet;
    const RunObserver& observer = context.observer ? *context.observer : quiet;
    const std::string name = stage.name();
    BemSolverOptions solver_options = stage.settings.solver;
    solver_options.hardness = stage.hardness;  // absent: purely elastic
    // Along a load path, the plastic deformation stays from one load to the next (unloading, reloading).
    solver_options.keep_plastic_deformation = stage.hardness && !stage.load_path.empty();
    solver_options.warning = [&](const std::string& text) { observer.warn(text); };
    // With an attraction, the adhesive solver around the same contact solver (bem/adhesive_solver.hpp).
    std::optional<BemSolver> solver;
    std::optional<AdhesiveBemSolver> adhesive;
    if (stage.adhesion)
      adhesive.emplace(
          solved, estar, *stage.adhesion,
          AdhesiveSolverOptions{.contact = solver_options, .method = stage.settings.adhesive_method},
          context.threads);
    else
      solver.emplace(solved, estar, solver_options, context.threads);
    std::map<int, Labeller> labellers;
    for (const int c : connectivities)
      labellers.emplace(c, Labeller(Topology::for_surface(c == 8 ? Connectivity::eight : Connectivity::four,
                                                          stage.periodic),
                                    context.threads));
    // The stiffness solves of the stage: planned once, to the stage tolerance (bem/contact_stiffness.hpp;
    // docs/solvers.md, "The stiffness solve").
    std::optional<ContactStiffnessSolver> stiffness_solver;
    if (stage.stiffness)
      stiffness_solver.emplace(solved.grid(), estar, stage.hardness, context.threads,
                               StiffnessOptions{.tolerance = kStageStiffnessTolerance});
    SolvedLoads done;
    const std::optional<std::size_t> measured_solve = stage.distributions_solve(mean_pressures, estar);
    for (std::size_t k = 0; k < mean_pressures.size(); ++k) {
      ContactSolution solution;
      HeightMap attraction;  // a = p - t of an adhesive state, for its fields
      if (adhesive) {
        const AdhesiveSolution& state = adhesive->solve(mean_pressures[k]);
        solution = state.contact();
        done.adhesive.push_back(state.adhesive());
        if (!fields.empty()) attraction = state.pressure - state.traction;
      } else {
        solution = solver->solve(mean_pressures[k]);
      }
      std::optional<Real> stiffness;
      if (stage.stiffness) {  // the linearised response of the converged state (docs/theory.md 12.2)
        const ContactStiffness response = stiffness_solver->solve(solution.pressure);
        if (!response.converged)
          observer.warn(name + ": load " + std::to_string(k + 1) +
                        ": the stiffness solve stopped unconverged at a relative residual of " +
                        std::to_string(response.residual) + "; its stiffness is left out (NaN)");
        stiffness = response.converged ? response.stiffness : std::nan("");
      }
      if (mirrored) solution = patch_of(solution, judged.nx, judged.ny, stage.hardness);
      for (auto& [c, labeller] : labellers)
        done.statistics[c].push_back(contact_statistics(solution, labeller));
      if (stiffness) done.stiffness.push_back(*stiffness);
      if (measured_solve == k)
        done.distributions = measure_distributions(solution.pressure, solution.gap, judged.dx() * judged.dy(),
                                                   stage.distributions->bins, labellers);
      if (!fields.empty()) {  // as each load is solved, so that a long run leaves what it has done
        write_load_fields(fields, k + 1, judged,
                          {.pressure = &solution.pressure,
                           .gap = &solution.gap,
                           .attraction = adhesive ? &attraction : nullptr},
                          [&](const std::string& text) { observer.warn(text); });
      }
      solution.pressure.resize(0, 0);
      solution.gap.resize(0, 0);
      observer.solved(bem_load_progress(name, solved.grid().nx, solved.grid().ny, k, mean_pressures.size(),
                                        mean_pressures[k] / estar,
                                        static_cast<long long>(solution.iterations), solution.seconds,
                                        std::chrono::duration<double>(Clock::now() - start).count()));
      done.solutions.push_back(std::move(solution));
    }
    // The approach-retract path after the loads, from a fresh approach (the solver forgets the loads).
    if (stage.approach_retract && adhesive)
      done.approach_retract = approach_retract(*adhesive, *stage.approach_retract);
    // The residual topography: the surface as the path left it (its plastic flow kept), heights from the
    // given surface's mean plane, in the project's text format (core/topography_io.hpp).
    if (!stage.settings.residual_topography.empty() && solver)
      write_surface(stage.settings.residual_topography, solver->surface());
    return done;
  }

  SweepCurve sweep(const StageSurface& surface, const SweepLevels& levels, const Topology& topology,
                   int threads) const override {
    return contactbench::sweep(whole(surface), levels, topology, threads);
  }
};

}  // namespace

const StageRunner& serial_runner() {
  static const SerialRunner runner;
  return runner;
}

}  // namespace contactbench
