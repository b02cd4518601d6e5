// contactbench sweep: bearing area and contact-spot count of {h > z} at many levels (docs/theory.md section
// 3). A front end over the scene pipeline: the surface is read as a scene's [surface] is (heights from the
// mean plane), the levels and connectivity as a plateau method's keys, and the sweep is the plateau model's
// stage (app/stages.hpp).
#include <charconv>
#include <iostream>
#include <string>

#include "contactbench/app/cli.hpp"
#include "contactbench/app/flag_scene.hpp"
#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/methods/registry.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/scene_toml.hpp"
#include "contactbench/app/stages.hpp"

namespace contactbench {

namespace {

struct SweepOptions {
  TopographyOptions topography;
  std::string levels = "exact";
  std::optional<int> connectivity;
  std::string out;
  int threads = 1;
};

const FlagNames kFlags = {{"surface.file", "FILE"},
                          {"surface.size", "--size"},
                          {"methods.sweep.levels", "--levels"},
                          {"methods.sweep.connectivity", "--connectivity"}};

void write_csv(std::ostream& out, const SweepCurve& curve, const std::string& file) {
  out << "# contactbench sweep of " << file << ": " << describe(curve.topology)
      << "; row j: the set {h > z}, z from the mean plane [m]; area_fraction_nodes = nodes in the set / "
         "all\n";
  out << "z,area_fraction_nodes,spots\n";
  for (std::size_t j = 0; j < curve.z.size(); ++j)
    out << json_number(curve.z[j]) << ',' << json_number(curve.area_fraction[j]) << ',' << curve.spots[j]
        << '\n';
}

void run_sweep(const SweepOptions& o, const CommandContext& command_context) {
  const std::string command = "contactbench sweep";
  // --levels K is an integer key, "exact" and "paper" strings, as in a scene.
  toml::table plateau{{"method", "plateau"}};
  std::int64_t count = 0;
  const auto [end, error] = std::from_chars(o.levels.data(), o.levels.data() + o.levels.size(), count);
  if (error == std::errc() && end == o.levels.data() + o.levels.size())
    plateau.insert("levels", count);
  else
    plateau.insert("levels", o.levels);
  if (o.connectivity) plateau.insert("connectivity", *o.connectivity);
  const toml::table document{{"surface", surface_keys(o.topography)},
                             {"methods", toml::table{{"sweep", plateau}}}};

  if (!o.out.empty()) check_output_file(o.out, o.topography.file, "--out");
  Problems problems(command);
  const Section root(document, "", problems, true);
  const auto surface = read_surface_keys(root, std::filesystem::current_path());
  std::unique_ptr<Method> method = MethodRegistry::global().make("plateau");
  method->read(Section(*document["methods"]["sweep"].as_table(), "methods.sweep", problems), {});
  try {
    problems.throw_if_any();
  } catch (const SceneError& e) {
    rethrow_with_flags(e, command, kFlags);
  }
  const Surface heights = make_surface(*surface, o.threads);
  const SceneContext context{.surface_points = heights.grid().nx,
                             .surface_periodic = heights.grid().periodic};
  const SweepStage stage = *method->needs(context).sweep;
  const RunObserver observer = terminal_observer(command);
  const SweepProducts products = run_sweep_stage(
      stage, heights, {.threads = o.threads, .observer = &observer, .stage_runner = command_context.runner});
  write_output(o.out, [&](std::ostream& out) { write_csv(out, products.sweep, o.topography.file); });
}

}  // namespace

void add_sweep_command(CLI::App& parent, const CommandContext& context) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* command = parent.add_subcommand(
      "sweep",
      "Cut a surface with planes: bearing area fraction A_c(z)/A0 and number of contact spots N(z) of "
      "{h > z}, heights measured from the mean plane, written as CSV (z, area_fraction_nodes, spots): the "
      "sweep a plateau method of a scene runs (scenes/README.md), with the same keys and defaults.");
  options->topography.add_to(*command, "spots wrap around in x and y");
  command->add_option("--levels", options->levels,
                      "'exact' (every distinct height, the default), K (K+1 equally spaced levels from the "
                      "highest to the lowest height) or 'paper' (500 steps of 0.002 h_max down to the mean "
                      "plane)");
  command->add_option("--connectivity", options->connectivity, "4 or 8");
  command->add_option("--out", options->out, "CSV file (default: standard output)")
      ->check(refuse_empty_output_name);
  add_threads_option(*command, options->threads);
  command->callback([options, &context] { run_sweep(*options, context); });
}

}  // namespace contactbench
