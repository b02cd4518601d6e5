#include "contactbench/app/stages.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>

#if CONTACTBENCH_WITH_MPI
#include "contactbench/app/distributed_stages.hpp"
#endif
#include "contactbench/core/generation.hpp"
#include "contactbench/core/labelling.hpp"
#include "contactbench/core/topography_io.hpp"
#include "contactbench/theories/plateau_model.hpp"

namespace contactbench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

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

Connectivity connectivity_of(int neighbours) {
  return neighbours == 8 ? Connectivity::eight : Connectivity::four;
}

}  // namespace

SolverKind default_bem_solver() {
#if CONTACTBENCH_WITH_MPI
  if (stages_are_distributed()) return kDefaultDistributedSolver;
#endif
  return kDefaultSolver;
}

std::string field_path(const std::string& prefix, std::size_t k, const char* what) {
  return prefix + "_load" + std::to_string(k) + "_" + what + ".txt";
}

std::string SweepStage::name() const {
  return "sweep (" +
         (refine > 0 ? "refined to " + std::to_string(refine) + " x " + std::to_string(refine) + ", "
                     : std::string()) +
         describe(levels) + ", " + describe(topology) + ")";
}

bool SweepStage::same_as(const SweepStage& other) const {
  return refine == other.refine && topology.connectivity == other.topology.connectivity &&
         topology.wrap_x == other.topology.wrap_x && topology.wrap_y == other.topology.wrap_y &&
         levels.kind == other.levels.kind &&
         (levels.kind == SweepLevels::Kind::exact || levels.count == other.levels.count);
}

std::string BemStage::name() const {
  std::ostringstream text;
  text << "bem (";
  if (refine > 0) text << "refined to " << refine << " x " << refine << ", ";
  text << solver_name(solver) << ", " << (periodic ? "periodic" : "non-periodic") << ", tolerance "
       << tolerance;
  if (single_precision) text << ", single precision";
  if (hardness) text << ", hardness " << *hardness << " Pa";
  if (extrapolate) text << ", again on twice the points a side for the extrapolated area";
  text << ")";
  return text.str();
}

SweepProducts run_sweep_stage(const SweepStage& stage, const Surface& surface, const StageContext& context) {
  const auto start = Clock::now();
  SweepProducts products;
  // The same surface on a finer grid (docs/theory.md section 2): the pixel effect of the cut's area and
  // spot count shrinks, the surface does not change (docs/theory.md section 8).
  std::optional<Surface> refined;
  if (stage.refine > 0) refined = refine(surface, stage.refine, stage.refine, context.threads);
  const Surface& swept = refined ? *refined : surface;
#if CONTACTBENCH_WITH_MPI
  if (stages_are_distributed())  // on slabs across the MPI ranks (app/distributed_stages.hpp)
    products.sweep = sweep_distributed(swept, stage.levels, stage.topology);
  else
#endif
    products.sweep = sweep(swept, stage.levels, stage.topology, context.threads);
  products.model = plateau_model(products.sweep);
  products.seconds = seconds_since(start);
  return products;
}

namespace {

// Every load on one grid, warm-started in increasing order; statistics per connectivity. `fields`: prefix
// of the per-load field files, empty for none.
void solve_loads(const BemStage& stage, const Surface& solved, Real estar,
                 const std::vector<Real>& mean_pressures, const std::set<int>& connectivities,
                 const StageContext& context, const std::string& fields, Clock::time_point start,
                 std::vector<ContactSolution>& solutions,
                 std::map<int, std::vector<ContactStatistics>>& statistics,
                 [[maybe_unused]] std::size_t& bytes_per_rank) {
  const RunObserver quiet;
  const RunObserver& observer = context.observer ? *context.observer : quiet;
  const std::string name = stage.name();
#if CONTACTBENCH_WITH_MPI
  if (stages_are_distributed()) {  // on slabs across the MPI ranks (app/distributed_stages.hpp)
    DistributedLoads done =
        solve_loads_distributed(stage, solved, estar, mean_pressures, connectivities, context.threads, fields,
                                [&](const std::string& text) { observer.warn(text); });
    solutions = std::move(done.solutions);
    statistics = std::move(done.statistics);
    bytes_per_rank = std::max(bytes_per_rank, done.bytes_per_rank);
    return;
  }
#endif
  PolonskyKeerOptions solver_options{.tolerance = stage.tolerance,
                                     .max_iterations = stage.max_iterations,
                                     .hardness = stage.hardness,  // absent: purely elastic
                                     .single_precision = stage.single_precision,
                                     .warning = [&](const std::string& text) { observer.warn(text); },
                                     .solver = stage.solver};
  PolonskyKeer solver(solved, estar, solver_options, context.threads);
  std::map<int, Labeller> labellers;
  for (const int c : connectivities)
    labellers.emplace(c,
                      Labeller(Topology::for_surface(connectivity_of(c), stage.periodic), context.threads));
  for (std::size_t k = 0; k < mean_pressures.size(); ++k) {
    ContactSolution solution = solver.solve(mean_pressures[k]);
    for (auto& [c, labeller] : labellers)
      statistics[c].push_back(contact_statistics(solution, labeller));
    if (!fields.empty()) {  // as each load is solved, so that a long run leaves what it has done
      write_surface(field_path(fields, k + 1, "pressure"), Surface(solved.grid(), solution.pressure));
      write_surface(field_path(fields, k + 1, "gap"), Surface(solved.grid(), solution.gap));
    }
    solution.pressure.resize(0, 0);
    solution.gap.resize(0, 0);
    if (seconds_since(start) > kProgressAfterSeconds) {
      std::ostringstream line;
      line << name << ": " << solved.grid().nx << " x " << solved.grid().ny << ": load " << k + 1 << " of "
           << mean_pressures.size() << " (P/(E* A0) = " << mean_pressures[k] / estar
           << "): " << solution.iterations << " iterations, " << solution.seconds << " s";
      observer.say(line.str());
    }
    solutions.push_back(std::move(solution));
  }
}

}  // namespace

BemProducts run_bem_stage(const BemStage& stage, const Surface& surface, Real estar,
                          const std::vector<Real>& mean_pressures, const std::set<int>& connectivities,
                          const StageContext& context) {
  const auto start = Clock::now();
  BemProducts products;
  Surface solved = stage.refine > 0 ? refine(surface, stage.refine, stage.refine, context.threads) : surface;
  const Index nx = solved.grid().nx, ny = solved.grid().ny;
  if (solved.grid().periodic != stage.periodic) solved = solved.with_periodic(stage.periodic);
  products.points = solved.grid().points();
  products.periodic = stage.periodic;
  products.hardness = stage.hardness;
  solve_loads(stage, solved, estar, mean_pressures, connectivities, context, stage.fields, start,
              products.solutions, products.statistics, products.bytes_per_rank);
  if (stage.extrapolate) {
    // The same surface on twice the points a side (the method's preflight refuses a non-periodic one):
    // refined from the scene's surface, not from the first grid (the same trigonometric interpolation).
    Surface fine = refine(surface, 2 * nx, 2 * ny, context.threads);
    if (fine.grid().periodic != stage.periodic) fine = fine.with_periodic(stage.periodic);
    products.fine_points = fine.grid().points();
    solve_loads(stage, fine, estar, mean_pressures, connectivities, context, "", start,
                products.fine_solutions, products.fine_statistics, products.bytes_per_rank);
  }
  products.seconds = seconds_since(start);
  return products;
}

}  // namespace contactbench
