// contactbench run SCENE: the paper's comparison for any surface (issue: scenes, the comparison run).
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>

#include <unistd.h>

#include "contactbench/app/adhesive_path_plot.hpp"
#include "contactbench/app/cli.hpp"
#include "contactbench/app/comparison.hpp"
#include "contactbench/app/distribution_plots.hpp"
#include "contactbench/app/fftw_wisdom_file.hpp"
#include "contactbench/app/load_area_plots.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/output_folder.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/report_writers.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/app/scene_toml.hpp"
#include "contactbench/app/unconverged.hpp"
#include "contactbench/core/fft.hpp"

namespace contactbench {

namespace {

struct RunCommandOptions {
  std::string scene;
  std::string out;          // default runs/<name>/ (untracked; results/ holds the published record)
  std::string fftw_wisdom;  // --fftw-wisdom FILE (app/fftw_wisdom_file.hpp); empty: the default
  int threads = 1;
  std::optional<Index> grid;  // --grid N (app/scene_grid_override.hpp); absent: the scene's own grid
  bool progress = false;      // --progress (app/cli.hpp terminal_observer)
  bool plots = true;
  bool quiet = false;
};

// The folder `.<name>.fields.<pid>` beside the output folder `<name>`: made at once, removed when empty at
// the end (a run whose scene asks for no fields); a failed run leaves its fields there.
class FieldsWorkFolder {
 public:
  explicit FieldsWorkFolder(const std::filesystem::path& output) {
    const std::filesystem::path absolute = std::filesystem::absolute(output).lexically_normal();
    const std::filesystem::path named = absolute.has_filename() ? absolute : absolute.parent_path();
    path_ = named.parent_path() / ("." + named.filename().string() + ".fields." + std::to_string(::getpid()));
    std::filesystem::create_directories(path_);
  }
  FieldsWorkFolder(const FieldsWorkFolder&) = delete;
  FieldsWorkFolder& operator=(const FieldsWorkFolder&) = delete;
  ~FieldsWorkFolder() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);  // only when empty: what a failed run solved is kept
  }
  const std::filesystem::path& path() const { return path_; }
  // Moves every file and folder written into `staging` (the same file system: renames).
  void move_into(const std::filesystem::path& staging) const {
    for (const auto& entry : std::filesystem::directory_iterator(path_))
      std::filesystem::rename(entry.path(), staging / entry.path().filename());
  }

 private:
  std::filesystem::path path_;
};

void run_command(const RunCommandOptions& o, const CommandContext& context) {
  // Everything validated before any work.
  const Scene scene = o.grid ? read_scene_on_grid(o.scene, *o.grid) : read_scene(o.scene);
  const std::filesystem::path folder =
      o.out.empty() ? std::filesystem::path("runs") / scene.name : std::filesystem::path(o.out);
  std::string command = "contactbench run " + o.scene + " --threads " + std::to_string(o.threads);
  if (o.grid) command += " --grid " + std::to_string(*o.grid);
  if (!o.out.empty()) command += " --out " + o.out;
  if (!o.plots) command += " --no-plots";

  check_replaceable_folder(folder);  // before any work, and again when the output is moved into place
  const RunObserver observer = terminal_observer("contactbench run", o.progress);
  // Warnings about the wisdom file are shown even with --quiet: they say why a run plans again.
  // Under mpiexec rank 0's wisdom includes FFTW-MPI's plans: a file of its own (core/fftw_wisdom.hpp).
  FftwWisdomFile wisdom(o.fftw_wisdom, o.threads, context.runs_as_ranks(), observer.warning);
  const double planning_before = fftw_planning_seconds();
  // A scene's fields are written, load by load, into a work folder beside the output (a run that fails
  // leaves there what it solved) and moved into the output folder with the rest.
  const FieldsWorkFolder fields(folder);
  SceneReport report = run_scene(scene, {.threads = o.threads,
                                         .observer = o.quiet ? nullptr : &observer,
                                         .runner = context.runner,
                                         .fields_folder = fields.path()});
  wisdom.save();
  // Planning as a line of its own in "Stages that ran", its time also counted in the stages that planned.
  report.stages.push_back({"fftw planning (included in the stages above; " + wisdom.describe() + ")",
                           fftw_planning_seconds() - planning_before});
  const Comparison comparison = compare(report);
  const Provenance provenance = current_provenance(o.threads, command);
  write_folder_atomically(folder, [&](const std::filesystem::path& staging) {
    write_report(staging, report, comparison, provenance);
    fields.move_into(staging);
    if (o.plots) {
      draw_load_area_plots(staging, report, std::cerr);
      draw_distribution_plots(staging, report, std::cerr);  // only when the scene asked for distributions
      for (const MethodResult& m : report.methods)  // only when the scene asked for an approach_retract path
        if (m.curve.approach_retract) try {
            const std::filesystem::path csv = staging / (m.label + "_approach_retract.csv");
            draw_adhesive_path_picture(csv, std::filesystem::path(csv).replace_extension(".png"),
                                       std::filesystem::path(csv).replace_extension(".svg"));
          } catch (const Error& e) {
            std::cerr << "contactbench run: warning: " << e.what() << " (the numbers are in the CSV)\n";
          }
    }
  });
  if (!o.quiet) {
    write_table_md(std::cout, report, comparison, provenance);
    std::cout << "\nWritten to " << folder.string() << "/ (curves.csv, summary.json, table.md"
              << (o.plots ? ", load_area.png, load_area.svg" : "") << ").\n";
  }
  throw_if_unconverged(report);  // written and marked, but not a success (app/unconverged.hpp)
}

}  // namespace

void add_run_command(CLI::App& parent, const CommandContext& context) {
  auto options = std::make_shared<RunCommandOptions>();
  CLI::App* command = parent.add_subcommand(
      "run",
      "Run a scene (a TOML file: surface, material, loads, methods, reference; see scenes/README.md): every "
      "method's load-area curve, its error against the reference and its cost in time, written as "
      "curves.csv, "
      "summary.json, table.md and load-area plots.");
  command->add_option("SCENE", options->scene, "scene file (TOML)")->required();
  command->add_option("--out", options->out, "output folder (default: runs/<scene name>/, which git ignores)")
      ->check(refuse_empty_output_name);
  command
      ->add_option("--grid", options->grid,
                   "points a side of the generated surface instead of the scene's surface.generate.grid: "
                   "the same size, spectrum and seed at another resolution (a quick look), every refine "
                   "key scaled by N/grid; refused for a surface read from a file (see surface.crop) and "
                   "below the least grid that resolves the spectrum (the error says which)")
      ->check(CLI::Range(Index{2}, Index{kMaxPointsASide}));
  command->add_flag("!--no-plots", options->plots, "do not draw the plots (no gnuplot run)");
  command->add_flag("--quiet", options->quiet, "no progress and no table on the terminal");
  add_threads_option(*command, options->threads);
  add_progress_option(*command, options->progress);
  add_fftw_wisdom_option(*command, options->fftw_wisdom);
  command->callback([options, &context] { run_command(*options, context); });
}

}  // namespace contactbench
