// contactbench bem: the boundary-element ground truth (Polonsky-Keer) at a list of loads, as a load-area CSV.
// A front end over the scene pipeline: its flags make a one-method scene (method bem), run and written as a
// scene's curves.csv is, so the validation, defaults, progress and columns are those of `contactbench run`.
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "contactbench/app/cli.hpp"
#include "contactbench/app/flag_scene.hpp"
#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/report_writers.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/app/unconverged.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

struct BemOptions {
  TopographyOptions topography;
  bool non_periodic = false;
  std::vector<Real> loads;
  std::optional<Real> modulus;  // E* [Pa]; default: the paper's material, E = 100 GPa, nu = 0.3
  std::optional<Real> tolerance;
  std::optional<Index> max_iterations;
  std::optional<Real> hardness;
  bool single_precision = false;
  std::string fields;
  std::optional<int> connectivity;
  std::optional<std::string> solver;  // bem/solver_registry.hpp
  bool allow_unconverged = false;
  std::string out;
  int threads = 1;
};

const FlagNames kFlags = {{"surface.file", "FILE"},
                          {"surface.size", "--size"},
                          {"material.estar", "--modulus"},
                          {"loads.values", "--loads"},
                          {"methods.bem.tolerance", "--tolerance"},
                          {"methods.bem.max_iterations", "--max-iterations"},
                          {"interface.hardness", "--hardness"},
                          {"methods.bem.precision", "--float"},
                          {"methods.bem.fields", "--fields"},
                          {"methods.bem.connectivity", "--connectivity"},
                          {"methods.bem.periodic", "--non-periodic"},
                          {"methods.bem.solver", "--solver"},
                          {"methods.bem.allow_unconverged", "--allow-unconverged"}};

// The one-method scene the flags describe: only what was given, so that every default is the scene's.
toml::table scene_of(const BemOptions& o) {
  toml::table material;
  if (o.modulus)
    material.insert("estar", *o.modulus);
  else
    material = toml::table{{"E", 100e9}, {"nu", 0.3}};  // the paper's material (docs/theory.md section 2)
  toml::array loads;
  for (const Real load : o.loads)
    loads.push_back(load);
  toml::table bem{{"method", "bem"}};
  if (o.non_periodic) bem.insert("periodic", false);
  if (o.tolerance) bem.insert("tolerance", *o.tolerance);
  if (o.max_iterations) bem.insert("max_iterations", static_cast<std::int64_t>(*o.max_iterations));
  if (o.single_precision) bem.insert("precision", "single");
  if (!o.fields.empty()) bem.insert("fields", o.fields);
  if (o.connectivity) bem.insert("connectivity", *o.connectivity);
  if (o.solver) bem.insert("solver", *o.solver);
  if (o.allow_unconverged) bem.insert("allow_unconverged", true);
  toml::table document{{"name", "bem"},
                       {"surface", surface_keys(o.topography)},
                       {"material", material},
                       {"loads", toml::table{{"values", loads}}},
                       {"methods", toml::table{{"bem", bem}}}};
  if (o.hardness) document.insert("interface", toml::table{{"hardness", *o.hardness}});
  return document;
}

// The command as given, every option that changes the result included, so that the header reruns it.
std::string command_line(const BemOptions& o) {
  const TopographyOptions& t = o.topography;
  std::string text = "contactbench bem " + t.file + " --loads";
  for (std::size_t k = 0; k < o.loads.size(); ++k)
    text += (k ? "," : " ") + json_number(o.loads[k]);
  auto add = [&](const char* flag, const auto& value) {
    if (value) text += std::string(" ") + flag + " " + json_number(static_cast<double>(*value));
  };
  add("--size", t.size);
  add("--size-y", t.size_y);
  if (t.periodic) text += " --periodic";
  if (o.non_periodic) text += " --non-periodic";
  if (t.channel) text += " --channel " + *t.channel;
  if (t.fill != "none") text += " --fill " + t.fill;
  if (t.level != "none") text += " --level " + t.level;
  add("--modulus", o.modulus);
  add("--tolerance", o.tolerance);
  add("--max-iterations", o.max_iterations);
  add("--hardness", o.hardness);
  if (o.single_precision) text += " --float";
  if (!o.fields.empty()) text += " --fields " + o.fields;
  add("--connectivity", o.connectivity);
  if (o.solver) text += " --solver " + *o.solver;
  if (o.allow_unconverged) text += " --allow-unconverged";
  return text + " --threads " + std::to_string(o.threads);
}

void run_bem(const BemOptions& o, const CommandContext& context) {
  if (o.topography.periodic && o.non_periodic) throw Error("--periodic and --non-periodic: give one of them");
  const std::string command = "contactbench bem";
  if (!o.out.empty()) check_output_file(o.out, o.topography.file, "--out");
  const Scene scene = scene_from_flags(scene_of(o), command, kFlags);
  const RunObserver observer = terminal_observer(command);
  SceneReport report;
  try {
    report = run_scene(scene, {.threads = o.threads, .observer = &observer, .runner = context.runner});
  } catch (const SceneError& error) {
    rethrow_with_flags(error, command, kFlags);
  }
  const Provenance provenance = current_provenance(o.threads, command_line(o));
  write_output(o.out, [&](std::ostream& out) { write_curves_csv(out, report, provenance); });
  throw_if_unconverged(report);  // written and marked, but not a success (app/unconverged.hpp)
}

}  // namespace

void add_bem_command(CLI::App& parent, const CommandContext& context) {
  auto options = std::make_shared<BemOptions>();
  CLI::App* command = parent.add_subcommand(
      "bem",
      "Solve the contact of the surface with a rigid flat by the boundary-element method (Polonsky-Keer) at "
      "each load, in increasing order, and write the load-area curve as CSV: the curves.csv of a one-method "
      "scene (scenes/README.md, method bem), with the same defaults and columns.");
  options->topography.add_to(*command, "the Fourier half-space; the default is the file's own periodicity");
  command->add_flag("--non-periodic", options->non_periodic,
                    "treat the surface as non-periodic (zero-padded half-space with Love's kernel)");
  command->add_option("--loads", options->loads, "loads P/(E* A0) > 0, comma-separated")
      ->required()
      ->delimiter(',');
  command->add_option("--modulus", options->modulus, "E* [Pa] (default: E = 100 GPa, nu = 0.3: 109.9 GPa)");
  command->add_option("--tolerance", options->tolerance,
                      "convergence: relative change of the pressure in one iteration (default: the scene's, "
                      "1e-8; 1e-6, the smallest it accepts, with --float)");
  command->add_option(
      "--hardness", options->hardness,
      "H [Pa]: cap the pressure at H, perfectly plastic (points at H are plastic: the surface "
      "flows to fit the flat there, gap 0); adds the CSV column plastic_fraction. Every load "
      "must be below H/E*");
  command->add_flag("--float", options->single_precision,
                    "iterate in single precision: half the memory, faster on large grids; results agree with "
                    "double to float's accuracy (area to 1e-3, mean gap to 1e-4)");
  command
      ->add_option("--fields", options->fields,
                   "PREFIX: write the pressure [Pa] and gap [m] of the k-th load solved (k = 1, 2, ... in "
                   "increasing load) to PREFIX_load<k>_pressure.txt and PREFIX_load<k>_gap.txt, in the "
                   "project's surface format (lossless, with the grid; read back by stats and the "
                   "library's read_topography), each written to a temporary file and renamed")
      ->check(refuse_empty_output_name);
  command->add_option("--max-iterations", options->max_iterations, "iteration cap per load (default 20000)");
  command->add_option("--connectivity", options->connectivity, "4 or 8, for counting contact spots");
  std::string known;
  for (const std::string& name : solver_names())
    known += (known.empty() ? "" : ", ") + name;
  command->add_option("--solver", options->solver,
                      "the BEM iteration: " + known + " (default " +
                          std::string(solver_name(kDefaultSolver)) +
                          ", which has no distributed version: as several MPI ranks name another; "
                          "docs/solvers.md); recorded in the CSV's header");
  command->add_flag("--allow-unconverged", options->allow_unconverged,
                    "exit 0 even when a load did not converge (its row still says converged = 0); without "
                    "it such a run exits with status 3 after writing its results");
  command->add_option("--out", options->out, "CSV file (default: standard output)")
      ->check(refuse_empty_output_name);
  add_threads_option(*command, options->threads);
  command->callback([options, &context] { run_bem(*options, context); });
}

}  // namespace contactbench
