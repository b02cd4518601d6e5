// contactbench sweep: bearing area and contact-spot count of {h > z} at many levels (docs/theory.md section
// 3). A front end over the scene pipeline: its flags make a one-method scene (a plateau method, whose sweep
// this is), run as `contactbench run` runs a scene, so the validation, defaults, preflight, progress and
// errors are run's; the output is the method's level curve, as a run writes it to <label>_levels.csv.
#include <charconv>
#include <string>

#include "contactbench/app/cli.hpp"
#include "contactbench/app/flag_scene.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/report_writers.hpp"
#include "contactbench/app/scene_run.hpp"

namespace contactbench {

namespace {

struct SweepOptions {
  TopographyOptions topography;
  std::string levels = "exact";
  std::optional<int> connectivity;
  std::string out;
  int threads = 1;
  bool progress = false;  // --progress (app/cli.hpp terminal_observer)
};

const FlagNames kFlags = {{"surface.file", "FILE"},
                          {"surface.size", "--size"},
                          {"methods.sweep.levels", "--levels"},
                          {"methods.sweep.connectivity", "--connectivity"}};

// The one-method scene the flags describe: only what was given, so that every default is the scene's. A
// scene needs a material and loads, which the level curve does not depend on: the paper's material and one
// load, which the plateau model answers on any surface (its preflight refuses none).
toml::table scene_of(const SweepOptions& o) {
  // --levels K is an integer key, "exact" and "paper" strings, as in a scene.
  toml::table plateau{{"method", "plateau"}, {"write_levels", true}};
  std::int64_t count = 0;
  const auto [end, error] = std::from_chars(o.levels.data(), o.levels.data() + o.levels.size(), count);
  if (error == std::errc() && end == o.levels.data() + o.levels.size())
    plateau.insert("levels", count);
  else
    plateau.insert("levels", o.levels);
  if (o.connectivity) plateau.insert("connectivity", *o.connectivity);
  return toml::table{{"name", "sweep"},
                     {"surface", surface_keys(o.topography)},
                     {"material", toml::table{{"E", 100e9}, {"nu", 0.3}}},
                     {"loads", toml::table{{"values", toml::array{1e-2}}}},
                     {"methods", toml::table{{"sweep", plateau}}}};
}

void run_sweep(const SweepOptions& o, const CommandContext& context) {
  const std::string command = "contactbench sweep";
  if (!o.out.empty()) check_output_file(o.out, o.topography.file, "--out");
  const Scene scene = scene_from_flags(scene_of(o), command, kFlags);
  const RunObserver observer = terminal_observer(command, o.progress);
  SceneReport report;
  try {
    report = run_scene(scene, {.threads = o.threads,
                               .observer = &observer,
                               .runner = context.runner,
                               .fields_folder = {},
                               .whole_file_surface = true});
  } catch (const SceneError& error) {
    rethrow_with_flags(error, command, kFlags);
  }
  write_output(o.out, [&](std::ostream& out) {
    write_levels_csv(out, *report.methods.front().curve.levels, "contactbench sweep of " + o.topography.file);
  });
}

}  // namespace

void add_sweep_command(CLI::App& parent, const CommandContext& context) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* command = parent.add_subcommand(
      "sweep",
      "Cut a surface with planes: bearing area fraction A_c(z)/A0 and number of contact spots N(z) of "
      "{h > z}, heights measured from the mean plane, written as CSV (z, area_fraction_nodes, spots): the "
      "sweep a plateau method of a scene runs, with the same keys and defaults, as `contactbench run` writes "
      "it to <label>_levels.csv (scenes/README.md).");
  options->topography.add_to(*command, "spots wrap around in x and y");
  command->add_option("--levels", options->levels,
                      "'exact' (every distinct height, the default), K (K+1 equally spaced levels from the "
                      "highest to the lowest height) or 'paper' (500 steps of 0.002 h_max down to the mean "
                      "plane)");
  command->add_option("--connectivity", options->connectivity, "4 or 8");
  command->add_option("--out", options->out, "CSV file (default: standard output)")
      ->check(refuse_empty_output_name);
  add_threads_option(*command, options->threads);
  add_progress_option(*command, options->progress);
  command->callback([options, &context] { run_sweep(*options, context); });
}

}  // namespace contactbench
