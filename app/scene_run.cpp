#include "contactbench/app/scene_run.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>

#if CONTACTBENCH_WITH_MPI
#include "contactbench/app/distributed_stages.hpp"
#endif
#include "contactbench/app/scene_plan.hpp"
#include "contactbench/app/scene_toml.hpp"

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

  // The inputs every preflight reads: the surface (heights from the mean plane) and its moments.
  std::optional<Surface> made;
  run_stage(report, observer, "surface", [&] { made = make_surface(scene.surface, options.threads); });
  const Surface& surface = *made;
  report.grid = surface.grid();
  const ScenePlan plan = plan_scene(scene, surface.grid());
  double moments_seconds = 0;
  if (plan.moments)
    moments_seconds = run_stage(report, observer, "moments",
                                [&] { report.moments = spectral_moments(surface, options.threads); });

  // Every preflight, before any stage: one SceneError lists every problem of every method.
  Problems problems(origin_of(scene));
  for (const MethodSpec& m : scene.methods)
    m.method->preflight(MethodCheck{.scene = scene,
                                    .surface = surface,
                                    .moments = report.moments,
                                    .key = "methods." + m.label,
                                    .problems = problems});
#if CONTACTBENCH_WITH_MPI
  // Run as several MPI ranks: a BEM stage the distributed solver cannot do is refused here, before any work.
  if (stages_are_distributed()) {
    report.ranks = distributed_rank_count();
    for (std::size_t m = 0; m < scene.methods.size(); ++m)
      if (const int b = plan.of_method[m].bem; b >= 0)
        if (const std::string refusal = distributed_bem_refusal(plan.bems[static_cast<std::size_t>(b)].stage);
            !refusal.empty())
          problems.add(0, "methods." + scene.methods[m].label, refusal);
  }
#endif
  problems.throw_if_any();

  const StageContext context{.threads = options.threads, .observer = &observer};
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
    const MethodNeeds needs = spec.method->needs(plan.context);
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
                        .curve = {},
                        .seconds = 0};
    result.seconds = run_stage(report, observer, "evaluate " + spec.label,
                               [&] { result.curve = spec.method->evaluate(inputs); });
    if (needs.moments) result.seconds += moments_seconds;
    if (inputs.sweep) result.seconds += inputs.sweep->seconds;
    if (inputs.bem) result.seconds += inputs.bem->seconds;
    report.methods.push_back(std::move(result));
  }
  report.seconds = seconds_since(run_start);
  return report;
}

}  // namespace contactbench
