#include "contactbench/app/stages.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <optional>
#include <sstream>

#include "contactbench/app/stage_runner.hpp"
#include "contactbench/core/generation.hpp"
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

std::size_t bytes_of(const Surface& surface) {
  return static_cast<std::size_t>(surface.heights().size()) * sizeof(Real);
}
std::size_t bytes_of(const std::optional<Surface>& surface) {
  return surface ? bytes_of(*surface) : 0;
}

}  // namespace

const StageRunner& StageContext::runner() const {
  return stage_runner ? *stage_runner : serial_runner();
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

std::optional<std::size_t> BemStage::distributions_solve(const std::vector<Real>& mean_pressures,
                                                         Real estar) const {
  if (!distributions) return std::nullopt;
  for (std::size_t k = 0; k < mean_pressures.size(); ++k)
    if (std::abs(mean_pressures[k] - distributions->load * estar) <= 1e-12 * mean_pressures[k]) return k;
  return std::nullopt;
}

std::string BemStage::name() const {
  const BemSolverOptions& solver = settings.solver;
  std::ostringstream text;
  text << "bem (";
  if (settings.refine > 0) text << "refined to " << settings.refine << " x " << settings.refine << ", ";
  text << solver_name(solver.solver) << ", "
       << (periodic                            ? "periodic"
           : settings.mirrored.value_or(false) ? "non-periodic mirrored"
           : as_is_because.empty()             ? "non-periodic"
                                               : "non-periodic as is (" + as_is_because + ")")
       << ", tolerance " << solver.tolerance;
  if (solver.single_precision) text << ", single precision";
  if (hardness) text << ", hardness " << *hardness << " Pa";
  if (adhesion) {
    text << ", adhesion " << adhesion_model_name(adhesion->model) << " w " << adhesion->work << " J/m^2";
    if (adhesion->model == AdhesionModel::dugdale)
      text << " sigma0 " << adhesion->stress << " Pa";
    else
      text << " rho " << adhesion->range << " m";
  }
  if (stiffness) text << ", with the linearised stiffness";
  if (distributions) text << ", with the distributions at load " << distributions->load;
  if (approach_retract)
    text << ", then the approach-retract path " << approach_retract->start << " -> " << approach_retract->turn
         << " m in " << approach_retract->steps << " steps a leg";
  if (settings.extrapolate) text << ", again on twice the points a side for the extrapolated area";
  if (settings.extrapolate && uses_third_grid(settings.error_estimate))
    text << " and on a third grid for its error bar";
  if (!load_path.empty())
    text << ", along the load path as listed (" << load_path.size() << " steps)"
         << (hardness ? ", keeping the plastic deformation" : "");
  text << ")";
  return text.str();
}

bool BemStage::operator==(const BemStage& other) const {
  return periodic == other.periodic && hardness == other.hardness && adhesion == other.adhesion &&
         load_path == other.load_path && stiffness == other.stiffness &&
         distributions.has_value() == other.distributions.has_value() &&
         (!distributions || (distributions->load == other.distributions->load &&
                             distributions->bins == other.distributions->bins)) &&
         approach_retract.has_value() == other.approach_retract.has_value() &&
         (!approach_retract || (approach_retract->start == other.approach_retract->start &&
                                approach_retract->turn == other.approach_retract->turn &&
                                approach_retract->steps == other.approach_retract->steps)) &&
         same_settings(bem_settings(), SettingScope::solve, settings, other.settings);
}

SweepProducts run_sweep_stage(const SweepStage& stage, const SceneSurface& surface,
                              const StageContext& context) {
  const auto start = Clock::now();
  SweepProducts products;
  // The same surface on a finer grid (docs/theory.md section 2): the pixel effect of the cut's area and
  // spot count shrinks, the surface does not change (docs/theory.md section 8).
  std::optional<Surface> refined;
  if (stage.refine > 0) refined = refine(surface.whole(), stage.refine, stage.refine, context.threads);
  const std::size_t held = surface.whole_bytes() + bytes_of(refined);
  const StageSurface swept = refined              ? StageSurface{refined->grid(), &*refined, held}
                             : surface.resident() ? StageSurface{surface.grid(), nullptr, held}
                                                  : StageSurface{surface.grid(), &surface.whole(), held};
  products.sweep = context.runner().sweep(swept, stage.levels, stage.topology, context.threads);
  products.model = plateau_model(products.sweep);
  products.seconds = seconds_since(start);
  return products;
}

BemProducts run_bem_stage(const BemStage& stage, const SceneSurface& scene_surface, Real estar,
                          const std::vector<Real>& mean_pressures, const std::set<int>& connectivities,
                          const StageContext& context) {
  const auto start = Clock::now();
  BemProducts products;
  const Index refined = stage.settings.refine;
  // The resident slabs solve as they are: no whole copy here (docs/mpi.md).
  const bool mirrored = stage.settings.mirrored.value_or(false);  // resolved (resolve_boundary)
  const bool on_slabs = scene_surface.resident() && refined == 0;
  std::optional<Surface> solved;
  Grid solved_grid = scene_surface.grid();
  if (!on_slabs) {
    const Surface& surface = scene_surface.whole();
    solved = refined > 0 ? refine(surface, refined, refined, context.threads) : surface;
    solved_grid = solved->grid();
  }
  const Index nx = solved_grid.nx, ny = solved_grid.ny;
  if (solved_grid.periodic != stage.periodic) {
    solved_grid.periodic = stage.periodic;
    if (solved) solved = solved->with_periodic(stage.periodic);
  }
  // boundary = "mirrored" (preflight: non-periodic problems only): the runner solves the periodic even
  // extension of this patch and hands back the solution and statistics on the patch, which is judged.
  products.points = solved_grid.points();
  products.periodic = stage.periodic;
  products.mirrored = mirrored;
  products.as_is_because = stage.as_is_because;
  products.hardness = stage.hardness;
  products.adhesion = stage.adhesion;
  products.load_path = stage.load_path;
  // Along a load path the solves follow it, step by step, instead of the scene's ascending loads.
  std::vector<Real> path_pressures;  // [Pa]
  for (const Real load : stage.load_path)
    path_pressures.push_back(load * estar);
  const std::vector<Real>& solved_pressures = stage.load_path.empty() ? mean_pressures : path_pressures;
  std::string fields = stage.settings.fields;
  if (!fields.empty() && !context.fields_folder.empty()) {  // inside the run's output folder
    const std::filesystem::path prefix = context.fields_folder / fields;
    std::filesystem::create_directories(prefix.parent_path());
    fields = prefix.string();
  }
  SolvedLoads loads =
      context.runner().solve_loads(stage,
                                   StageSurface{.grid = solved_grid,
                                                .whole = solved ? &*solved : nullptr,
                                                .root_bytes = scene_surface.whole_bytes() + bytes_of(solved)},
                                   estar, solved_pressures, connectivities, fields, context);
  products.solutions = std::move(loads.solutions);
  products.statistics = std::move(loads.statistics);
  products.adhesive = std::move(loads.adhesive);
  products.stiffness = std::move(loads.stiffness);
  products.distributions = std::move(loads.distributions);
  products.approach_retract = std::move(loads.approach_retract);
  products.bytes_per_rank = loads.bytes_per_rank;
  if (stage.settings.extrapolate) {
    // The same surface on twice the points a side (the method's preflight refuses a non-periodic one):
    // refined from the scene's surface, not from the first grid (the same trigonometric interpolation).
    const Surface& surface = scene_surface.whole();
    Surface fine = refine(surface, 2 * nx, 2 * ny, context.threads);
    if (fine.grid().periodic != stage.periodic) fine = fine.with_periodic(stage.periodic);
    products.fine_points = fine.grid().points();
    // The stiffness is the first grid's (as the mean gap): not solved again on the finer one.
    BemStage fine_stage = stage;
    fine_stage.stiffness = false;
    fine_stage.distributions.reset();  // the first grid's, as the mean gap
    fine_stage.approach_retract.reset();
    SolvedLoads fine_loads = context.runner().solve_loads(
        fine_stage,
        StageSurface{
            .grid = fine.grid(), .whole = &fine, .root_bytes = scene_surface.whole_bytes() + bytes_of(fine)},
        estar, mean_pressures, connectivities, "", context);
    products.fine_solutions = std::move(fine_loads.solutions);
    products.fine_statistics = std::move(fine_loads.statistics);
    products.fine_adhesive = std::move(fine_loads.adhesive);
    products.bytes_per_rank = std::max(products.bytes_per_rank, fine_loads.bytes_per_rank);
    if (uses_third_grid(stage.settings.error_estimate)) {
      // The third grid of the error bar (docs/theory.md section 9.2): half the first grid when that still
      // holds the scene's surface, else twice the finer one.
      const bool coarser = third_grid_is_coarser(nx, ny, surface.grid().nx, surface.grid().ny);
      products.third_nx = coarser ? nx / 2 : 4 * nx;
      products.third_ny = coarser ? ny / 2 : 4 * ny;
      Surface third = products.third_nx == surface.grid().nx && products.third_ny == surface.grid().ny
                          ? surface
                          : refine(surface, products.third_nx, products.third_ny, context.threads);
      if (third.grid().periodic != stage.periodic) third = third.with_periodic(stage.periodic);
      SolvedLoads third_loads = context.runner().solve_loads(
          fine_stage,
          StageSurface{.grid = third.grid(),
                       .whole = &third,
                       .root_bytes = scene_surface.whole_bytes() + bytes_of(third)},
          estar, mean_pressures, connectivities, "", context);
      products.third_solutions = std::move(third_loads.solutions);
      products.third_statistics = std::move(third_loads.statistics);
      products.bytes_per_rank = std::max(products.bytes_per_rank, third_loads.bytes_per_rank);
    }
  }
  products.seconds = seconds_since(start);
  return products;
}

}  // namespace contactbench
