// Running a scene (docs/architecture.md, data flow): make the surface (heights from the mean plane), plan
// the stages (app/scene_plan.hpp), compute the moments; with the surface and its moments, the inputs every
// method is checked against, run EVERY
// method's preflight and refuse the scene with every problem, each at its key path, before any stage runs;
// then run each planned stage once and turn the products into each method's answer at the scene's loads.
#pragma once

#include <string>
#include <vector>

#include "contactbench/app/methods/method.hpp"
#include "contactbench/app/run_observer.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench {

struct StageRecord {
  std::string name;
  double seconds = 0;
};

struct MethodResult {
  std::string label;
  std::string method;         // the registry name
  std::string compared_area;  // which area curve.area_fraction is (Method::compared_area)
  // Shown after the label, in parentheses, in table.md and the plot legend (Method::note); empty: nothing.
  std::string note;
  // The scene's effects this method ran without (`ignore = [...]`, app/interface.hpp), by name; the note
  // says so too.
  std::vector<std::string> ignored_effects;
  MethodCurve curve;  // at the report's loads, report.scene.loads
  // Wall time of the stages the method needed (shared stages are charged in full to each method that needs
  // them) plus its own evaluation; making the scene's surface is charged to no method.
  double seconds = 0;

  // " (<note>)", or "" when there is none: what the tables and the legend add after the label.
  std::string note_suffix() const { return note.empty() ? std::string() : " (" + note + ")"; }
};

struct SceneReport {
  Scene scene;              // as run: its loads are the loads of every curve, held once
  Grid grid;                // of the scene's surface (before any refinement a method asks for)
  SpectralMoments moments;  // of the scene's surface (profile moments, docs/theory.md section 1)
  // When the surface is a line scan (app/line_scan_surface.hpp): what the report says of it; `grid` is then
  // the profile's one row and `moments` those of the isotropic surface it samples. Empty: heights over an
  // area.
  std::string line_scan;
  std::vector<StageRecord> stages;    // every stage that ran, in order
  std::vector<MethodResult> methods;  // in the scene's order
  int threads = 1;
  // MPI ranks the distributed stages ran on (app/distributed_stages.hpp; 1: one process), and the largest
  // memory one rank held for a BEM solve [bytes] (0 when none ran distributed).
  int ranks = 1;
  std::size_t bytes_per_rank = 0;
  // Bytes of the scene's whole heights this process held (0 when they stayed on the ranks' slabs,
  // app/scene_surface.hpp).
  std::size_t root_surface_bytes = 0;
  double seconds = 0;  // the whole run
  const std::vector<Real>& loads() const { return scene.loads; }
};

class StageRunner;  // app/stage_runner.hpp

struct RunOptions {
  int threads = 1;
  const RunObserver* observer = nullptr;  // stages, progress and warnings; null: quiet
  const StageRunner* runner = nullptr;    // where the heavy stages run; null: this process
  // Where a scene's `fields` (a relative prefix) are written: the run's output folder, or the folder whose
  // files are moved there (app/run_command.cpp). Empty: prefixes are paths as given (relative to the working
  // directory), as `contactbench bem --fields` has them.
  std::filesystem::path fields_folder = {};
  // Read a surface file whole on this process even where the runner could read it in slabs
  // (StageRunner::read_resident_surface): `contactbench sweep` writes the heights themselves as its levels,
  // one process's bit for bit, which the slabs' mean (added in rank order) would move in the last bit.
  bool whole_file_surface = false;
};

// Throws SceneError listing every problem the preflights found (then no sweep, solve or theory has run).
SceneReport run_scene(const Scene& scene, const RunOptions& options);

}  // namespace contactbench
