// contactbench bem: the boundary-element ground truth (Polonsky-Keer) at a list of loads, as a load-area CSV.
// A front end over the scene pipeline: its flags make a one-method scene (method bem), run and written as a
// scene's curves.csv is, so the validation, defaults, progress and columns are those of `contactbench run`.
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "contactbench/app/adhesive_path_csv.hpp"
#include "contactbench/app/cli.hpp"
#include "contactbench/app/fftw_wisdom_file.hpp"
#include "contactbench/app/flag_scene.hpp"
#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/methods/bem_settings.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/report_writers.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/app/setting_flags.hpp"
#include "contactbench/app/surface_source.hpp"
#include "contactbench/app/unconverged.hpp"
#include "contactbench/bem/adhesive_path.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench {

namespace {

// Convolutions of the finest grid's operator per load of the default solver, measured by counting them on
// the 1024^2 periodic surface of docs/solvers.md's Planning (one cold load: 22; a 12-load curve: 433), with
// room: the planner measures a curve's plans without a wisdom file when loads x this exceeds its pay-back
// count. Plain Polonsky-Keer iterates about 15 times as often, so for it this undercounts (estimates more).
constexpr double kApplicationsPerLoad = 40;

struct BemOptions {
  TopographyOptions topography;
  std::vector<Real> loads;
  std::optional<Real> modulus;   // E* [Pa]; default: the paper's material, E = 100 GPa, nu = 0.3
  std::optional<Real> hardness;  // the interface's effect (app/interface.hpp)
  // The interface's adhesion as "MODEL,KEY=VALUE,KEY=VALUE" (interface.adhesion's keys in the scene's order).
  std::string adhesion;
  // --approach-retract FROM,TO,STEPS: separation control along a closed path instead of --loads.
  std::vector<Real> approach_retract;
  // The BEM method's keys, each a flag as its declaration says (app/methods/bem_settings.cpp).
  SettingFlags settings{[] {
    std::vector<SettingSpec> specs;
    for (const Setting<BemSettings>& row : bem_settings())
      specs.push_back(spec_of(row));
    return specs;
  }()};
  std::string out;
  std::string fftw_wisdom;  // --fftw-wisdom FILE (app/fftw_wisdom_file.hpp); empty: the default
  int threads = 1;
  bool progress = false;  // --progress (app/cli.hpp terminal_observer)
};

FlagNames flag_names(const BemOptions& o) {
  FlagNames names = {{"surface.file", "FILE"},
                     {"surface.size", "--size"},
                     {"material.estar", "--modulus"},
                     {"loads.values", "--loads"},
                     {"interface.hardness", "--hardness"}};
  for (const char* key : {"model", "work", "stress", "range"})
    names["interface.adhesion." + std::string(key)] = "--adhesion " + std::string(key);
  o.settings.name_flags("methods.bem.", names);
  return names;
}

// --adhesion "dugdale,work=0.05,stress=1e5": the model, then KEY=VALUE numbers; the scene's reader checks
// them (each named as --adhesion KEY).
toml::table adhesion_keys(const std::string& text) {
  const std::string accepted =
      "accepted: --adhesion dugdale,work=W,stress=SIGMA0 or --adhesion exponential,work=W,range=RHO";
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  toml::table table{{"model", parts.front()}};
  for (std::size_t k = 1; k < parts.size(); ++k) {
    const std::size_t equals = parts[k].find('=');
    if (equals == std::string::npos)
      throw Error("--adhesion: \"" + parts[k] + "\" is not KEY=VALUE; " + accepted);
    const std::string key = parts[k].substr(0, equals), value = parts[k].substr(equals + 1);
    const std::optional<double> number = formats::parse_real(value);
    if (!number) throw Error("--adhesion: " + key + " = \"" + value + "\" is not a number; " + accepted);
    table.insert(key, *number);
  }
  return table;
}

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
  // The path needs no load, but the scene's reader (which checks the surface, material and adhesion for it)
  // needs one: it is never solved for.
  if (!o.approach_retract.empty()) loads = toml::array{1.0};
  toml::table bem{{"method", "bem"}};
  o.settings.insert_into(bem);
  toml::table document{{"name", "bem"},
                       {"surface", surface_keys(o.topography)},
                       {"material", material},
                       {"loads", toml::table{{"values", loads}}},
                       {"methods", toml::table{{"bem", bem}}}};
  toml::table interface;
  if (o.hardness) interface.insert("hardness", *o.hardness);
  if (!o.adhesion.empty()) interface.insert("adhesion", adhesion_keys(o.adhesion));
  if (!interface.empty()) document.insert("interface", interface);
  return document;
}

// The command as given, every option that changes the result included, so that the header reruns it.
std::string command_line(const BemOptions& o) {
  const TopographyOptions& t = o.topography;
  std::string text = "contactbench bem " + t.file;
  for (std::size_t k = 0; k < o.loads.size(); ++k)
    text += (k ? "," : " --loads ") + json_number(o.loads[k]);
  auto add = [&](const char* flag, const auto& value) {
    if (value) text += std::string(" ") + flag + " " + json_number(static_cast<double>(*value));
  };
  add("--size", t.size);
  add("--size-y", t.size_y);
  if (t.periodic) text += " --periodic";
  if (t.channel) text += " --channel " + *t.channel;
  if (t.fill != "none") text += " --fill " + t.fill;
  if (t.level != "none") text += " --level " + t.level;
  add("--modulus", o.modulus);
  add("--hardness", o.hardness);
  if (!o.adhesion.empty()) text += " --adhesion " + o.adhesion;
  if (!o.approach_retract.empty())
    text += " --approach-retract " + json_number(o.approach_retract[0]) + "," +
            json_number(o.approach_retract[1]) + "," + json_number(o.approach_retract[2]);
  return text + o.settings.command_text() + " --threads " + std::to_string(o.threads);
}

// --approach-retract: the adhesive BEM along the closed separation path (bem/adhesive_path.hpp), written as
// app/adhesive_path_csv.hpp says.
void run_approach_retract(const BemOptions& o, const Scene& scene, const std::string& command) {
  if (!scene.interface.adhesion)
    throw Error("--approach-retract needs --adhesion (the path of a non-adhesive contact has no jumps)");
  if (scene.interface.hardness)
    throw Error("--approach-retract with --hardness: adhesion with a hardness is not modelled");
  const std::vector<Real>& path = o.approach_retract;
  const Real steps = path[2];
  if (!(path[1] < path[0]) || !(steps >= 2) || steps != std::floor(steps) || steps > 1e6)
    throw Error(
        "--approach-retract FROM,TO,STEPS: needs TO < FROM (separations [m]) and a whole STEPS >= 2, "
        "got " +
        json_number(path[0]) + "," + json_number(path[1]) + "," + json_number(steps));
  const Surface surface = make_surface(scene.surface, o.threads);
  const Real modulus = scene.material.estar;
  // The BEM's settings as the scene's method reads them (its solver, tolerance, periodicity).
  const BemStage stage = *scene.method("bem")
                              .method
                              ->needs({.surface_points = std::nullopt,
                                       .surface_periodic = surface.grid().periodic,
                                       .folder = {},
                                       .interface = scene.interface})
                              .bem;
  if (stage.settings.refine > 0 || stage.settings.extrapolate || !stage.settings.fields.empty())
    throw Error("--approach-retract: --refine, --extrapolate and --fields are not taken along a path");
  // Not through the scene's preflight: a declared mirror, unavailable with adhesion, is refused here.
  if (stage.settings.mirrored.value_or(false))
    throw Error(
        "--approach-retract: --boundary mirrored is not taken with adhesion (the path is solved as is)");
  const RunObserver observer = terminal_observer(command);
  AdhesiveSolverOptions options{.contact = stage.settings.solver, .method = stage.settings.adhesive_method};
  options.contact.warning = observer.warning;
  AdhesiveBemSolver solver(surface.with_periodic(stage.periodic), modulus, *stage.adhesion, options,
                           o.threads);
  const AdhesivePath result =
      approach_retract(solver, {.start = path[0], .turn = path[1], .steps = static_cast<Index>(steps)});
  const Provenance provenance = current_provenance(o.threads, command_line(o));
  write_output(o.out, [&](std::ostream& out) {
    write_adhesive_path_csv(out, result, modulus, surface.grid().nx * surface.grid().ny,
                            "contactbench bem approach-retract path", provenance);
  });
  if (!result.converged) throw Error("contactbench bem: some states of the path did not converge (marked 0)");
}

void run_bem(const BemOptions& o, const CommandContext& context) {
  const std::string command = "contactbench bem";
  if (o.loads.empty() == o.approach_retract.empty())
    throw Error("contactbench bem: give --loads or --approach-retract (one of them)");
  const FlagNames flags = flag_names(o);
  const toml::table document = scene_of(o);
  if (o.topography.periodic && document["methods"]["bem"]["periodic"].value_or(true) == false)
    throw Error("--periodic and --non-periodic: give one of them");
  if (!o.out.empty()) check_output_file(o.out, o.topography.file, "--out");
  const Scene scene = scene_from_flags(document, command, flags);
  if (!o.approach_retract.empty()) return run_approach_retract(o, scene, command);
  const RunObserver observer = terminal_observer(command, o.progress);
  // The planner's estimate of the run's work on its finest grid (core/fft.hpp FftWork; docs/solvers.md,
  // Planning): kApplicationsPerLoad convolutions a load, so that a long curve without a wisdom file measures.
  set_fft_work({.expected_applications = static_cast<double>(o.loads.size()) * kApplicationsPerLoad});
  // Under mpiexec rank 0's wisdom includes FFTW-MPI's plans: a file of its own (core/fftw_wisdom.hpp).
  FftwWisdomFile wisdom(o.fftw_wisdom, o.threads, context.runs_as_ranks(), observer.warning);
  const double planning_before = fftw_planning_seconds();
  SceneReport report;
  try {
    report = run_scene(scene, {.threads = o.threads, .observer = &observer, .runner = context.runner});
  } catch (const SceneError& error) {
    rethrow_with_flags(error, command, flags);
  }
  wisdom.save();
  // Reported as the stages are (app/cli.cpp: when it is long), as part of the bem stage's time.
  observer.finished("FFTW planning (part of the bem stage; " + wisdom.describe() + ")",
                    fftw_planning_seconds() - planning_before);
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
  command->add_option("--loads", options->loads, "loads P/(E* A0) > 0, comma-separated")->delimiter(',');
  command
      ->add_option(
          "--approach-retract", options->approach_retract,
          "instead of --loads, with --adhesion: FROM,TO,STEPS: the flat's separation d [m] (as in the "
          "CSV's separation column) from FROM down to TO in STEPS equal steps, then back, each state "
          "starting from the last; writes one row per state and, as comment lines, the jumps into and "
          "out of contact, the pull-off and the cycle's energy balance (docs/theory.md section 10.7)")
      ->expected(3)
      ->delimiter(',');
  command->add_option("--modulus", options->modulus, "E* [Pa] (default: E = 100 GPa, nu = 0.3: 109.9 GPa)");
  command->add_option(
      "--hardness", options->hardness,
      "H [Pa]: the interface's hardness (the scene's interface.hardness): cap the pressure at H, perfectly "
      "plastic (points at H are plastic: the surface flows to fit the flat there, gap 0); adds the CSV "
      "columns plastic_area_fraction and plastic_load_fraction. Every load must be below H/E*");
  command->add_option(
      "--adhesion", options->adhesion,
      "the interface's adhesion (the scene's interface.adhesion): dugdale,work=W,stress=SIGMA0 "
      "(Maugis-Dugdale: "
      "SIGMA0 [Pa] while the gap is below W/SIGMA0, W [J/m^2]) or exponential,work=W,range=RHO ((W/RHO) "
      "exp(-g/RHO), RHO [m]); loads are then net loads, the area the repulsive contact's, and the CSV gains "
      "adhesive_load, attractive_fraction, zone_pixels and outer_iterations (docs/theory.md section 10)");
  options->settings.add_to(*command);
  command->add_option("--out", options->out, "CSV file (default: standard output)")
      ->check(refuse_empty_output_name);
  add_threads_option(*command, options->threads);
  add_progress_option(*command, options->progress);
  add_fftw_wisdom_option(*command, options->fftw_wisdom);
  command->callback([options, &context] { run_bem(*options, context); });
}

}  // namespace contactbench
