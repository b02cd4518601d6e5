#include "contactbench/app/scene_run.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>
#include <variant>

#include "contactbench/app/line_scan_surface.hpp"
#include "contactbench/app/problems.hpp"
#include "contactbench/app/scene_plan.hpp"
#include "contactbench/app/stage_runner.hpp"

namespace contactbench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Runs `work` as a stage: tells the observer, records it in the report, returns its seconds.
template <class Work>
double run_stage(SceneReport& report, const RunObserver& observer, const std::string& name, Work&& work) {
  observer.started(name);
  const auto start = Clock::now();
  work();
  const double seconds = seconds_since(start);
  report.stages.push_back({name, seconds});
  observer.finished(name, seconds);
  return seconds;
}

// Every method against the scene's interface (app/interface.hpp): an effect it does not model is refused
// unless its table ignores it; an ignore that changes nothing is a mistake worth saying.
void check_effects(const Scene& scene, Problems& problems) {
  for (const MethodSpec& m : scene.methods) {
    const std::vector<Effect> modelled = m.method->models();
    const std::string key = "methods." + m.label;
    for (const Effect e : scene.interface.effects()) {
      const bool models = std::find(modelled.begin(), modelled.end(), e) != modelled.end();
      const bool ignores = std::find(m.ignored.begin(), m.ignored.end(), e) != m.ignored.end();
      if (!models && !ignores)
        problems.add(0, key,
                     "the method " + std::string(m.name()) + " does not model the interface's " +
                         std::string(effect_name(e)) + " (interface." + std::string(effect_name(e)) + ")",
                     "a method that models it, or ignore = [\"" + std::string(effect_name(e)) + "\"] in [" +
                         key + "] to run it without, its rows marked");
    }
    for (const Effect e : m.ignored)
      if (!scene.interface.has(e))
        problems.add(
            0, key + ".ignore",
            "ignores " + std::string(effect_name(e)) + ", which the scene's [interface] does not call for",
            "only effects of [interface]: " + (scene.interface.effects().empty()
                                                   ? std::string("none here (remove ignore)")
                                                   : effects_text(scene.interface.effects())));
  }
}

std::string origin_of(const Scene& scene) {
  return scene.file.empty() ? "<scene>" : scene.file.string();
}

}  // namespace

SceneReport run_scene(const Scene& scene, const RunOptions& options) {
  const auto run_start = Clock::now();
  const RunObserver quiet;
  const RunObserver& observer = options.observer ? *options.observer : quiet;
  SceneReport report;
  report.scene = scene;
  report.threads = options.threads;

  // The inputs every preflight reads: the surface (heights from the mean plane) and its moments. Run as
  // several ranks, a generated surface is made on the ranks' slabs, never whole here (app/scene_surface.hpp).
  const StageRunner& runner = options.runner ? *options.runner : serial_runner();
  std::optional<SceneSurface> made;
  std::optional<LineScanSurface> line_scan;
  run_stage(report, observer, "surface", [&] {
    if (is_line_scan(scene.surface)) {
      line_scan = read_line_scan_surface(scene.surface);
      made.emplace(line_scan->profile);
      report.line_scan = describe(*line_scan);
      return;
    }
    if (const auto* generated = std::get_if<GeneratedSurfaceSpec>(&scene.surface.source);
        generated && generated->refine == 0)  // the refinement is serial (docs/mpi.md)
      if (auto resident = runner.make_resident_surface(*generated, options.threads)) {
        made.emplace(std::move(*resident));
        return;
      }
    if (const auto* file = std::get_if<FileSurfaceSpec>(&scene.surface.source);
        file && !options.whole_file_surface)
      if (auto resident = runner.read_resident_surface(*file, options.threads)) {
        made.emplace(std::move(*resident));
        return;
      }
    made.emplace(make_surface(scene.surface, options.threads));
  });
  const SceneSurface& surface = *made;
  report.grid = surface.grid();
  const ScenePlan plan = plan_scene(scene, surface.grid());
  double moments_seconds = 0;
  if (plan.moments)
    moments_seconds = run_stage(report, observer, "moments", [&] {
      report.moments = line_scan                    ? line_scan->moments
                       : surface.resident_moments() ? *surface.resident_moments()
                                                    : spectral_moments(surface.whole(), options.threads);
    });

  // Every preflight, before any stage: one SceneError lists every problem of every method.
  Problems problems(origin_of(scene));
  check_effects(scene, problems);
  for (const MethodSpec& m : scene.methods) {
    const SceneContext context = method_context(plan.context, scene, m);
    if (line_scan && m.method->needs(context).heights_over_an_area) {
      problems.add(0, "methods." + m.label,
                   "the method " + std::string(m.name()) +
                       " needs heights over an area, and the surface is a line scan (one profile): only "
                       "the methods that read the surface's moments alone run on it",
                   "a 2-D file of the surface, or the analytic theories (gw_mccool, bgt, bgt_linear, "
                   "persson)");
      continue;
    }
    m.method->preflight(MethodCheck{.scene = scene,
                                    .interface = context.interface,
                                    .surface = surface,
                                    .moments = report.moments,
                                    .key = "methods." + m.label,
                                    .problems = problems,
                                    .fields_folder = options.fields_folder,
                                    .line_scan = line_scan ? &line_scan->statistics : nullptr,
                                    .runner = &runner});
  }
  // A BEM stage the runner cannot do (e.g. an option the distributed solver lacks) is refused here, before
  // any work, with the reason: never run with another solver than the scene says.
  report.ranks = runner.ranks();
  for (std::size_t m = 0; m < scene.methods.size(); ++m)
    if (const int b = plan.of_method[m].bem; b >= 0)
      if (const std::string refusal = runner.bem_refusal(plan.bems[static_cast<std::size_t>(b)].stage);
          !refusal.empty())
        problems.add(0, "methods." + scene.methods[m].label, refusal);
  problems.throw_if_any();

  const StageContext context{.threads = options.threads,
                             .observer = &observer,
                             .stage_runner = &runner,
                             .fields_folder = options.fields_folder};
  std::vector<SweepProducts> sweeps(plan.sweeps.size());
  for (std::size_t s = 0; s < plan.sweeps.size(); ++s)
    run_stage(report, observer, plan.sweeps[s].name(),
              [&] { sweeps[s] = run_sweep_stage(plan.sweeps[s], surface, context); });
  std::vector<BemProducts> bems(plan.bems.size());
  std::vector<Real> mean_pressures;  // [Pa]
  for (const Real load : scene.loads)
    mean_pressures.push_back(load * scene.material.estar);
  for (std::size_t b = 0; b < plan.bems.size(); ++b)
    run_stage(report, observer, plan.bems[b].stage.name(), [&] {
      bems[b] = run_bem_stage(plan.bems[b].stage, surface, scene.material.estar, mean_pressures,
                              plan.bems[b].connectivities, context);
      report.bytes_per_rank = std::max(report.bytes_per_rank, bems[b].bytes_per_rank);
    });

  for (std::size_t m = 0; m < scene.methods.size(); ++m) {
    const MethodSpec& spec = scene.methods[m];
    const ScenePlan::Stages& stages = plan.of_method[m];
    const MethodNeeds needs = spec.method->needs(method_context(plan.context, scene, spec));
    const MethodInputs inputs{
        .scene = scene,
        .surface = surface,
        .moments = report.moments,
        .sweep = stages.sweep >= 0 ? &sweeps[static_cast<std::size_t>(stages.sweep)] : nullptr,
        .bem = stages.bem >= 0 ? &bems[static_cast<std::size_t>(stages.bem)] : nullptr};
    MethodResult result{.label = spec.label,
                        .method = std::string(spec.name()),
                        .compared_area = spec.method->compared_area(),
                        .note = spec.method->note(),
                        .ignored_effects = {},
                        .curve = {},
                        .seconds = 0};
    // A method that runs without some of the scene's effects says so wherever its row shows.
    for (const Effect e : spec.ignored)
      result.ignored_effects.emplace_back(effect_name(e));
    if (const std::string mark = ignored_effects_note(spec.ignored); !mark.empty())
      result.note = result.note.empty() ? mark : result.note + "; " + mark;
    result.seconds = run_stage(report, observer, "evaluate " + spec.label,
                               [&] { result.curve = spec.method->evaluate(inputs); });
    if (needs.moments) result.seconds += moments_seconds;
    if (inputs.sweep) result.seconds += inputs.sweep->seconds;
    if (inputs.bem) result.seconds += inputs.bem->seconds;
    report.methods.push_back(std::move(result));
  }
  report.root_surface_bytes = surface.whole_bytes();
  report.seconds = seconds_since(run_start);
  return report;
}

}  // namespace contactbench
