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

// The surface a stage works on, made from the scene's: whole in this process (the scene's own, or a copy
// the stage owns), or on the ranks' slabs (the scene's resident ones, or a refinement the runner keeps
// there), of which this process has the grid.
class StageHeights {
 public:
  // The scene's surface as it is: its resident slabs stay on the ranks.
  static StageHeights of_scene(const SceneSurface& scene) {
    StageHeights h;
    h.grid_ = scene.grid();
    if (!scene.resident()) h.whole_ = &scene.whole();
    return h;
  }
  // The scene's surface Fourier-refined to nx x ny: on the ranks' slabs when the runner makes it there (no
  // rank holds it whole, docs/mpi.md), else here.
  static StageHeights refined(const SceneSurface& scene, Index nx, Index ny, const StageContext& context) {
    StageHeights h;
    const Surface& surface = scene.whole();
    if (context.runner().refine_on_slabs(surface, nx, ny, context.threads)) {
      h.grid_ = surface.grid();  // core's refine: the same sizes, nx x ny points, periodic
      h.grid_.nx = nx;
      h.grid_.ny = ny;
      h.grid_.periodic = true;
      h.refined_slabs_ = true;
      return h;
    }
    h.keep(refine(surface, nx, ny, context.threads));
    return h;
  }

  const Grid& grid() const { return grid_; }
  // The boundary the stage solves with (a whole surface copied with it when it differs).
  void set_periodic(bool periodic) {
    if (grid_.periodic == periodic) return;
    grid_.periodic = periodic;
    if (whole_) keep(whole_->with_periodic(periodic));
  }
  // Bytes of whole heights the stage itself holds here.
  std::size_t owned_bytes() const { return bytes_of(owned_); }
  StageSurface view(std::size_t root_bytes) const {
    return {.grid = grid_, .whole = whole_, .root_bytes = root_bytes, .refined_slabs = refined_slabs_};
  }

 private:
  void keep(Surface surface) {
    owned_ = std::move(surface);
    whole_ = &*owned_;
    grid_ = owned_->grid();
  }

  Grid grid_;
  const Surface* whole_ = nullptr;
  std::optional<Surface> owned_;
  bool refined_slabs_ = false;
};

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
  const StageHeights swept = stage.refine > 0
                                 ? StageHeights::refined(surface, stage.refine, stage.refine, context)
                                 : StageHeights::of_scene(surface);
  const StageSurface view = swept.view(surface.whole_bytes() + swept.owned_bytes());
  products.sweep = context.runner().sweep(view, stage.levels, stage.topology, context.threads);
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
  // The resident slabs solve as they are, and a refinement stays on the ranks' slabs when the runner keeps it
  // there: no whole copy here (docs/mpi.md), nor of the scene's whole heights unless the boundary differs.
  const bool mirrored = stage.settings.mirrored.value_or(false);  // resolved (resolve_boundary)
  StageHeights solved = refined > 0 ? StageHeights::refined(scene_surface, refined, refined, context)
                                    : StageHeights::of_scene(scene_surface);
  const Grid scene_grid = solved.grid();  // before the stage's boundary
  solved.set_periodic(stage.periodic);
  const Grid& solved_grid = solved.grid();
  const Index nx = scene_grid.nx, ny = scene_grid.ny;
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
      context.runner().solve_loads(stage, solved.view(scene_surface.whole_bytes() + solved.owned_bytes()),
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
    StageHeights fine = StageHeights::refined(scene_surface, 2 * nx, 2 * ny, context);
    fine.set_periodic(stage.periodic);
    products.fine_points = fine.grid().points();
    // The stiffness is the first grid's (as the mean gap): not solved again on the finer one.
    BemStage fine_stage = stage;
    fine_stage.stiffness = false;
    fine_stage.distributions.reset();  // the first grid's, as the mean gap
    fine_stage.approach_retract.reset();
    SolvedLoads fine_loads =
        context.runner().solve_loads(fine_stage, fine.view(scene_surface.whole_bytes() + fine.owned_bytes()),
                                     estar, mean_pressures, connectivities, "", context);
    products.fine_solutions = std::move(fine_loads.solutions);
    products.fine_statistics = std::move(fine_loads.statistics);
    products.fine_adhesive = std::move(fine_loads.adhesive);
    products.bytes_per_rank = std::max(products.bytes_per_rank, fine_loads.bytes_per_rank);
    if (uses_third_grid(stage.settings.error_estimate)) {
      // The third grid of the error bar (docs/theory.md section 9.2): half the first grid when that still
      // holds the scene's surface, else twice the finer one.
      const Grid& scene = scene_surface.grid();
      const bool coarser = third_grid_is_coarser(nx, ny, scene.nx, scene.ny);
      products.third_nx = coarser ? nx / 2 : 4 * nx;
      products.third_ny = coarser ? ny / 2 : 4 * ny;
      StageHeights third =
          products.third_nx == scene.nx && products.third_ny == scene.ny
              ? StageHeights::of_scene(scene_surface)
              : StageHeights::refined(scene_surface, products.third_nx, products.third_ny, context);
      third.set_periodic(stage.periodic);
      SolvedLoads third_loads = context.runner().solve_loads(
          fine_stage, third.view(scene_surface.whole_bytes() + third.owned_bytes()), estar, mean_pressures,
          connectivities, "", context);
      products.third_solutions = std::move(third_loads.solutions);
      products.third_statistics = std::move(third_loads.statistics);
      products.bytes_per_rank = std::max(products.bytes_per_rank, third_loads.bytes_per_rank);
    }
  }
  products.seconds = seconds_since(start);
  return products;
}

}  // namespace contactbench
