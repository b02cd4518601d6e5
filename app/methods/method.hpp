// A method of the comparison (docs/architecture.md, "methods are objects"): one object per
// [methods.<label>] table, made by the registry (app/methods/registry.hpp) from the name in `method`. It
//   - reads its own keys (read) and writes them back with defaults filled in (write),
//   - declares the stages it needs (needs): the spectral moments, a sweep of one topology and levels, a BEM
//     solve of one grid, boundary, tolerance and effects; the planner runs the union of all needs, each once,
//   - checks itself against the surface, the material and the loads before any stage runs (preflight),
//     reporting every problem with the key path a user would change,
//   - and turns the stages' products into its answer at the scene's loads (evaluate).
// Adding a method: one file holding a class derived from Method, and one line in app/methods/registry.cpp
// (scenes/README.md, "Adding a method").
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "contactbench/app/compared_quantity.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_surface.hpp"
#include "contactbench/app/stages.hpp"
#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/profile_statistics.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/sweep.hpp"

namespace contactbench {

class Problems;
class StageRunner;  // app/stage_runner.hpp
class Section;
struct SceneKeys;

// What a scene knows about its surface: while its methods read their keys (before any file is read) the
// points a side when a generated surface says so; once the surface is made (planning), its periodicity.
// And the interface's effects as this method runs them: the scene's, less those the method ignores.
struct SceneContext {
  std::optional<Index> surface_points;  // points a side, when known
  bool surface_periodic = true;
  std::filesystem::path folder =
      {};  // the scene file's folder: relative paths of its keys resolve against it
  InterfaceSpec interface = {};
  std::vector<Real> load_path = {};  // the scene's loads.path = "as listed" (Scene::load_path); empty: none
};

// The stages one method needs; the planner unites them over the scene (app/scene_plan.hpp).
struct MethodNeeds {
  bool moments = false;
  std::optional<SweepStage> sweep = std::nullopt;
  std::optional<BemStage> bem = std::nullopt;
  int bem_connectivity = 4;  // the spot count this method reads from the BEM stage's contact maps
  // Whether it reads heights over an area (the sweep, the BEM, a fit to the surface's spectrum): then a line
  // scan, one profile, cannot drive it. The analytic theories read the moments alone (docs/formats.md "line
  // scans": a profile's moments are those of the isotropic surface it is a profile of).
  bool heights_over_an_area = true;
};

// What a preflight sees: everything known before the first stage (the surface and its moments are the
// scene's inputs), and where to report (each problem with its key path).
struct MethodCheck {
  const Scene& scene;
  const InterfaceSpec& interface;  // as this method runs it: the scene's less what it ignores
  const SceneSurface& surface;     // heights from the mean plane (whole on demand, app/scene_surface.hpp)
  const SpectralMoments& moments;
  std::string key;  // "methods.<label>"
  Problems& problems;
  // RunOptions::fields_folder: where a relative `fields` prefix lands (empty: the working directory).
  std::filesystem::path fields_folder = {};
  // The scene's surface is a line scan: `surface` is its profile as one row and `moments` those of the
  // isotropic surface it is a profile of (app/surface_source.hpp). Null: heights over an area.
  const ProfileStatistics* line_scan = nullptr;
  // Where the heavy stages will run (app/stage_runner.hpp); null: this process.
  const StageRunner* runner = nullptr;
  void problem(std::string_view key_suffix, std::string_view reason, std::string_view accepted = {}) const;
};

// What evaluate sees: the inputs and the products of the stages this method declared.
struct MethodInputs {
  const Scene& scene;
  const SceneSurface& surface;
  const SpectralMoments& moments;
  const SweepProducts* sweep = nullptr;  // when needs().sweep
  const BemProducts* bem = nullptr;      // when needs().bem
};

// A method's answer at the scene's loads (the loads themselves live once, in the scene of the report). The
// comparison, the tables and the plots read only these typed fields; `columns` are the method's own output.
struct MethodCurve {
  std::vector<Real> area_fraction;  // A/A0: the area the comparison uses (compared_area() says which)
  std::vector<Real> separation;     // [m] from the mean plane of the heights; NaN where the method has none
  std::vector<Real> spots;          // NaN where the method counts none
  // Filled only when the scene compares them (Scene::compare; docs/theory.md section 12): the mean gap u-bar
  // [m] and the contact stiffness per unit area K = -dP/dd [Pa/m], d the rigid approach of the flat. Empty:
  // the method cannot give the quantity (the tables say "n/a", never 0); NaN at a load without an answer.
  std::vector<Real> mean_gap;
  std::vector<Real> stiffness;
  // The values of a compared quantity: area_fraction, mean_gap or stiffness.
  const std::vector<Real>& values(Quantity quantity) const;
  std::string parameters;  // the method as run, for the report
  // The node count, contact nodes / all nodes, where the method has it beside its compared area (the tables'
  // "kappa (nodes ...)"); empty when it has none.
  std::vector<Real> area_fraction_nodes;
  // The method's own estimate of the error of area_fraction [A/A0] (the BEM's extrapolation error): the
  // reference's uncertainty in the tables. Empty when the method has none; NaN at a load without one.
  std::vector<Real> area_fraction_error;
  // Whether each load's iteration converged; empty when the method does not iterate. Unconverged loads are
  // marked in the tables, and a run with any exits non-zero unless the method accepts them (the BEM's
  // allow_unconverged = true; app/unconverged.hpp).
  std::vector<bool> converged;
  bool accepts_unconverged = false;
  // The sweep the curve was read from, level by level (a plateau method's, when asked: write_levels = true):
  // a run writes it beside the curves as <label>_levels.csv, `contactbench sweep` as its output.
  std::optional<SweepCurve> levels;
  // The method's own columns beside those above (e.g. the BEM's iterations), one value per load, and the
  // names of those summary.json repeats beside its area (the BEM's extrapolated area).
  std::vector<std::pair<std::string, std::vector<Real>>> columns;
  std::vector<std::string> summary_columns;
  // Along the scene's load path (loads.path = "as listed"), the method's columns one row per step, in the
  // path's order (the BEM's loops of loading and unloading): a run writes them as <label>_path.csv. Empty:
  // no path, or a method whose answer does not depend on it.
  std::vector<std::pair<std::string, std::vector<Real>>> path_columns;
  // At the scene's `distributions` load, the BEM's pressure, gap and patch-size distributions: a run writes
  // them as <label>_pressure_distribution.csv, _gap_distribution.csv and _patch_sizes.csv.
  std::optional<LoadDistributions> distributions;
  // After the loads, the scene's `approach_retract` path (the adhesive BEM's, bem/adhesive_path.hpp) and the
  // nodes of its grid (the area fractions' A0): a run writes it as <label>_approach_retract.csv with its
  // plot.
  std::optional<AdhesivePath> approach_retract;
  Index approach_retract_points = 0;

  // From a library's curve: checks that it answers at `loads` (Error otherwise) and drops its copy of them.
  static MethodCurve from(const LoadAreaCurve& curve, const std::vector<Real>& loads);
};

class Method {
 public:
  virtual ~Method() = default;

  virtual std::string_view name() const = 0;  // the registry name, `method = "..."`
  // The interface effects it models (app/interface.hpp); a scene calling for any other is refused unless
  // the method's table ignores it. Default: none (frictionless, elastic, non-adhesive).
  virtual std::vector<Effect> models() const { return {}; }
  // Whether it is the ground truth the others are judged against when a scene names no reference and it is
  // the only such method (the BEM).
  virtual bool is_ground_truth() const { return false; }
  // Which area its A/A0 is, as the tables say (e.g. "area_fraction_corrected: perimeter-corrected nodes").
  virtual std::string compared_area() const = 0;
  // What the report's tables and plot legend add after its label, in parentheses (e.g. "Hertz-consistent
  // plateaus, this project" for a variant that is not the paper's); empty: nothing.
  virtual std::string note() const { return {}; }

  // Reads the keys of [methods.<label>] other than `method`; every unknown key and bad value is a problem.
  virtual void read(const Section& keys, const SceneContext& context) = 0;
  // Its keys, defaults filled in, as read() accepts them again.
  virtual void write(SceneKeys& keys) const = 0;

  virtual MethodNeeds needs(const SceneContext& context) const = 0;
  // Every reason it cannot answer this scene, each a problem at a key path; nothing when it can.
  virtual void preflight(const MethodCheck& check) const = 0;
  virtual MethodCurve evaluate(const MethodInputs& inputs) const = 0;
};

// With a hardness H: one problem at interface.hardness naming every load whose mean pressure P/A0 = load E*
// is at or above H, `consequence` saying what that means for the method (the BEM and every plastic theory
// refuse it alike). Nothing without a hardness.
void check_hardness_above_loads(const MethodCheck& check, const std::string& consequence);

// A theory's own refusals, load by load: `solve_one_load` is called for each of the scene's loads and every
// distinct reason it throws becomes one problem, so that every refused load is named and a reason that is not
// about a load (the same for all of them) is given once.
void report_loads_the_theory_refuses(const MethodCheck& check,
                                     const std::function<void(Real)>& solve_one_load);

}  // namespace contactbench
