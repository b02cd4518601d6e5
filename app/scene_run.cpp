#include "contactbench/app/scene_run.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>

#include "contactbench/bem/contact_statistics.hpp"
#include "contactbench/bem/polonsky_keer.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/labelling.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/core/topography_io.hpp"
#include "contactbench/theories/bgt_linear.hpp"
#include "contactbench/theories/bush_gibson_thomas.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"
#include "contactbench/theories/persson.hpp"
#include "contactbench/theories/plateau_model.hpp"

namespace contactbench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Stages longer than this report their progress on the progress stream (the issue: "more than a couple of
// seconds").
constexpr double kProgressAfterSeconds = 2;

// Times `work` as a stage of the report and returns the seconds it took.
void record_stage(SceneReport& report, const std::string& name, double seconds, std::ostream* progress) {
  report.stages.push_back({name, seconds});
  if (progress && seconds > kProgressAfterSeconds)
    *progress << "contactbench run: " << name << ": done in " << seconds << " s\n";
}

template <class Work>
double run_stage(SceneReport& report, const std::string& name, std::ostream* progress, Work&& work) {
  const auto start = Clock::now();
  work(start);
  const double seconds = seconds_since(start);
  record_stage(report, name, seconds, progress);
  return seconds;
}

Surface make_surface(const SurfaceSpec& spec, int threads) {
  if (const auto* g = std::get_if<GeneratedSurfaceSpec>(&spec.source)) {
    const Grid grid{.nx = g->grid, .ny = g->grid, .lx = g->size, .ly = g->size, .periodic = true};
    const SelfAffinePsd psd{
        .sigma = g->sigma, .hurst = g->hurst, .qr = g->qr, .qs = g->qs, .anisotropy = g->anisotropy};
    validate(psd, grid);
    if (g->refine > 0)
      return synthesize(grid, generate_coefficients(grid, psd, g->seed), g->refine, g->refine, threads);
    return generate_surface(grid, psd, g->seed, threads);
  }
  const auto& file = std::get<FileSurfaceSpec>(spec.source);
  return read_topography(file.path, {.lx = file.size_x, .ly = file.size_y, .periodic = file.periodic});
}

// What one BEM stage leaves for the methods that share it: per load, the solver's scalars and the contact
// statistics for each connectivity asked for.
struct BemProducts {
  std::vector<ContactSolution> solutions;  // fields dropped (pressure and gap emptied) to keep memory small
  std::map<int, std::vector<ContactStatistics>> statistics;  // by connectivity
  double seconds = 0;                                        // refinement + solves + statistics
  Index points = 0;                                          // nodes of the grid solved on
};

BemProducts run_bem_stage(const BemStage& stage, const Surface& surface, const Scene& scene,
                          const std::set<int>& connectivities, const RunOptions& options,
                          SceneReport& report) {
  BemProducts products;
  Surface solved = surface;
  if (stage.refine > 0)
    products.seconds += run_stage(report,
                                  "refine to " + std::to_string(stage.refine) + " x " +
                                      std::to_string(stage.refine) + " (Fourier interpolation)",
                                  options.progress, [&](Clock::time_point) {
                                    solved = refine(surface, stage.refine, stage.refine, options.threads);
                                  });
  if (solved.grid().periodic != stage.periodic) solved = solved.with_periodic(stage.periodic);
  products.points = solved.grid().points();
  const std::string name = stage.name();
  products.seconds += run_stage(report, name, options.progress, [&](Clock::time_point start) {
    PolonskyKeerOptions solver_options;
    solver_options.tolerance = stage.tolerance;
    solver_options.max_iterations = stage.max_iterations;
    solver_options.hardness = stage.hardness;  // absent: purely elastic, no capped code runs
    solver_options.solver = stage.solver;
    PolonskyKeer solver(solved, scene.material.estar, solver_options, options.threads);
    std::map<int, Labeller> labellers;
    for (const int c : connectivities)
      labellers.emplace(c, Labeller(Topology::for_surface(c == 8 ? Connectivity::eight : Connectivity::four,
                                                          stage.periodic),
                                    options.threads));
    for (std::size_t k = 0; k < scene.loads.size(); ++k) {
      ContactSolution solution = solver.solve(scene.loads[k] * scene.material.estar);
      for (auto& [c, labeller] : labellers)
        products.statistics[c].push_back(contact_statistics(solution, labeller));
      solution.pressure.resize(0, 0);
      solution.gap.resize(0, 0);
      if (options.progress && seconds_since(start) > kProgressAfterSeconds)
        *options.progress << "contactbench run: " << name << ": load " << k + 1 << " of "
                          << scene.loads.size() << " (P/(E* A0) = " << scene.loads[k]
                          << "): " << solution.iterations << " iterations, " << solution.seconds << " s\n";
      products.solutions.push_back(std::move(solution));
    }
  });
  return products;
}

MethodResult bem_result(const MethodSpec& method, const BemStage& stage, const BemProducts& products,
                        const Scene& scene) {
  const auto& spec = std::get<BemMethodSpec>(method.options);
  const std::vector<ContactStatistics>& stats = products.statistics.at(spec.connectivity);
  MethodResult result;
  result.curve.method = "bem";
  result.curve.load = scene.loads;
  std::vector<Real> nodes, mean_gap, max_pressure, iterations, residual, converged, solve_seconds, plastic;
  for (std::size_t k = 0; k < scene.loads.size(); ++k) {
    const ContactSolution& s = products.solutions[k];
    result.curve.area_fraction.push_back(stats[k].area_fraction_corrected);
    result.curve.separation.push_back(s.separation);
    result.curve.spots.push_back(static_cast<Real>(stats[k].spots));
    nodes.push_back(stats[k].area_fraction);
    mean_gap.push_back(stats[k].mean_gap);
    max_pressure.push_back(stats[k].max_pressure);
    iterations.push_back(static_cast<Real>(s.iterations));
    residual.push_back(s.residual);
    converged.push_back(s.converged ? 1 : 0);
    solve_seconds.push_back(s.seconds);
    plastic.push_back(static_cast<Real>(s.plastic_points) / static_cast<Real>(products.points));
  }
  result.columns = {{"area_fraction_nodes", nodes},  {"mean_gap", mean_gap}, {"max_pressure", max_pressure},
                    {"iterations", iterations},      {"residual", residual}, {"converged", converged},
                    {"solve_seconds", solve_seconds}};
  if (spec.hardness) result.columns.emplace_back("plastic_fraction", plastic);  // nodes at p = H / all nodes
  result.curve.parameters = "Polonsky-Keer " + stage.name().substr(4) +
                            ", area perimeter-corrected (node count in area_fraction_nodes), spots by " +
                            std::to_string(spec.connectivity) + "-connectivity";
  result.seconds = products.seconds;
  return result;
}

// The moments a theory sees: the surface's own, or with anisotropy = "average" its equivalent isotropic
// surface (app/scene.hpp TheoryMethodSpec).
SpectralMoments theory_moments(const SpectralMoments& m, const TheoryMethodSpec& spec) {
  if (!spec.average_anisotropy) return m;
  const Real m2 = 0.5 * (m.m2x + m.m2y), m4 = 0.5 * (m.m4x + m.m4y);
  return {.m0 = m.m0, .m2x = m2, .m4x = m4, .m2y = m2, .m4y = m4};
}

LoadAreaCurve theory_curve_of(MethodKind kind, const SpectralMoments& moments, const Scene& scene,
                              Real area) {
  switch (kind) {
    case MethodKind::gw_mccool:
      return gw_mccool_curve(moments, scene.loads, area);
    case MethodKind::bgt:
      return bgt_curve(moments, scene.loads, area);
    case MethodKind::bgt_linear:
      return bgt_linear_curve(moments, scene.loads);
    case MethodKind::persson:
      return persson_curve(moments, scene.loads);
    case MethodKind::bem:
    case MethodKind::plateau:
      break;
  }
  throw Error("internal: " + std::string(to_string(kind)) + " is not an analytic theory");
}

LoadAreaCurve theory_curve(const MethodSpec& method, const SpectralMoments& surface_moments,
                           const Scene& scene, Real area) {
  const auto& spec = std::get<TheoryMethodSpec>(method.options);
  const SpectralMoments moments = theory_moments(surface_moments, spec);
  LoadAreaCurve curve = theory_curve_of(method.kind, moments, scene, area);
  if (spec.average_anisotropy)
    curve.parameters += "; anisotropy averaged: the equivalent isotropic surface of m2x/m2y = " +
                        std::to_string(surface_moments.m2x / surface_moments.m2y) +
                        ", m4x/m4y = " + std::to_string(surface_moments.m4x / surface_moments.m4y);
  return curve;
}

}  // namespace

SceneReport run_scene(const Scene& scene, const RunOptions& options) {
  const auto run_start = Clock::now();
  const ScenePlan plan = plan_scene(scene);  // refuses an impossible plan before any work
  SceneReport report;
  report.scene = scene;
  report.threads = options.threads;

  const auto surface_start = Clock::now();
  const Surface surface = make_surface(scene.surface, options.threads);
  record_stage(report, "surface", seconds_since(surface_start), options.progress);
  report.grid = surface.grid();
  // The moments serve the theories and the report's areal kappa (gbar): one FFT, no contact solve.
  const double moments_seconds = run_stage(report, "moments", options.progress, [&](Clock::time_point) {
    report.moments = spectral_moments(surface, options.threads);
  });

  std::vector<SweepCurve> sweeps(plan.sweeps.size());
  std::vector<LoadAreaCurve> plateau_models(plan.sweeps.size());
  std::vector<double> sweep_seconds(plan.sweeps.size());
  for (std::size_t s = 0; s < plan.sweeps.size(); ++s)
    sweep_seconds[s] = run_stage(report, plan.sweeps[s].name(), options.progress, [&](Clock::time_point) {
      sweeps[s] = sweep(surface, plan.sweeps[s].levels, plan.sweeps[s].topology, options.threads);
      plateau_models[s] = plateau_model(sweeps[s]);
    });

  std::vector<BemProducts> bem_products;
  for (std::size_t b = 0; b < plan.bems.size(); ++b) {
    std::set<int> connectivities;
    for (std::size_t m = 0; m < scene.methods.size(); ++m)
      if (scene.methods[m].kind == MethodKind::bem && plan.stage_of_method[m] == static_cast<int>(b))
        connectivities.insert(std::get<BemMethodSpec>(scene.methods[m].options).connectivity);
    bem_products.push_back(run_bem_stage(plan.bems[b], surface, scene, connectivities, options, report));
  }

  for (std::size_t m = 0; m < scene.methods.size(); ++m) {
    const MethodSpec& method = scene.methods[m];
    const int stage = plan.stage_of_method[m];
    MethodResult result;
    if (method.kind == MethodKind::bem) {
      const auto b = static_cast<std::size_t>(stage);
      result = bem_result(method, plan.bems[b], bem_products[b], scene);
    } else if (method.kind == MethodKind::plateau) {
      const auto start = Clock::now();
      const auto s = static_cast<std::size_t>(stage);
      result.curve = plateau_curve_at_loads(sweeps[s], plateau_models[s], scene.loads);
      result.seconds = sweep_seconds[static_cast<std::size_t>(stage)] + seconds_since(start);
    } else {
      double seconds = 0;
      const std::string kind(to_string(method.kind));
      run_stage(report, method.label == kind ? kind : kind + " (" + method.label + ")", options.progress,
                [&](Clock::time_point start) {
                  result.curve = theory_curve(method, report.moments, scene, surface.grid().nominal_area());
                  seconds = seconds_since(start);
                });
      result.seconds = moments_seconds + seconds;
    }
    result.label = method.label;
    result.kind = method.kind;
    result.curve.seconds = result.seconds;
    report.methods.push_back(std::move(result));
  }
  report.seconds = seconds_since(run_start);
  return report;
}

}  // namespace contactbench
