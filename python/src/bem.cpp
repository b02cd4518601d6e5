// The boundary-element ground truth as a solver object (bem/bem_solver.hpp, bem/contact_statistics.hpp,
// docs/theory.md section 6). Solves release the GIL. Ctrl-C is honoured between iterations: the solver's
// between_iterations hook takes the GIL, lets Python run its signal handlers and abandons the solve with
// KeyboardInterrupt (the solver then starts its next solve afresh). With `adhesion`, the adhesive solver
// (bem/adhesive_solver.hpp) around the same contact solver, as `contactbench bem --adhesion` runs it. With
// `hardness`, the elastic-perfectly plastic cap (docs/solvers.md "Hardness") as `contactbench bem --hardness`
// solves it, and the load path up and down keeping the plastic deformation (solve_path), as a scene's
// loads.path = "as listed" does.
#include <pybind11/stl.h>

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "bindings.hpp"
#include "contactbench/app/interface.hpp"
#include "contactbench/app/methods/bem_settings.hpp"
#include "contactbench/app/problems.hpp"
#include "contactbench/app/section.hpp"
#include "contactbench/bem/adhesive_path.hpp"
#include "contactbench/bem/adhesive_solver.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/contact_statistics.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::python {

namespace {

struct BemResult {
  ContactSolution solution;
  ContactStatistics statistics;
  Real modulus = 0;  // E* [Pa]
  // With an adhesion: what the attraction adds (the scene's adhesive columns), out of `points` nodes, and
  // whether no state in contact carries the load.
  std::optional<AdhesiveLoad> adhesive;
  Index points = 0;
  bool separated = false;
  // With a hardness: the cap H [Pa], for the plastic load fraction (None without).
  std::optional<Real> hardness = std::nullopt;
};

// The plastic nodes / all nodes, as the BEM method's plastic_area_fraction column
// (app/methods/bem_method.cpp).
Real plastic_area_fraction(const BemResult& r) {
  return static_cast<Real>(r.solution.plastic_points) / static_cast<Real>(r.points);
}

// H x the plastic area over P: the share of the load the plastic nodes carry, as the BEM method's
// plastic_load_fraction column (docs/theory.md section 6.7; 0 at no load).
Real plastic_load_fraction(const BemResult& r) {
  return r.solution.mean_pressure > 0 ? *r.hardness * plastic_area_fraction(r) / r.solution.mean_pressure : 0;
}

// A load path up and down (BemSolver.solve_path), as a scene's loads.path = "as listed" runs it
// (app/serial_runner.cpp): one result per step in the path's order, the loads as given, and the surface as
// the path left it (the residual topography; with a hardness only).
struct PythonLoadPath {
  std::vector<BemResult> results;
  std::vector<Real> loads;  // P/(E* A0)
  std::optional<Surface> residual_topography;
};

// An approach-retract path and what it needs to give its loads in the loads' unit and its areas as
// fractions, as the CLI's CSV does (app/adhesive_path_csv.cpp).
struct PythonAdhesivePath {
  AdhesivePath path;
  Real modulus = 0;  // E* [Pa]
  Index points = 0;
};

// One column of the path's states as a new numpy array.
template <class Value>
py::array path_column(const PythonAdhesivePath& p,
                      Value (*value)(const AdhesivePathState&, const PythonAdhesivePath&)) {
  std::vector<Value> column;
  for (const AdhesivePathState& state : p.path.states)
    column.push_back(value(state, p));
  return py::array(py::cast(column));
}

// The scene's interface table `document` read by the scene's own reader (app/interface.cpp): the same checks
// and messages, each key named as the caller wrote it (hardness, adhesion.KEY), not as interface.KEY.
InterfaceSpec read_python_interface(const toml::table& document) {
  Problems problems("BemSolver");
  InterfaceSpec spec = read_interface(Section(document, "", problems, true));
  try {
    problems.throw_if_any();
  } catch (const SceneError& error) {
    // "BemSolver: interface.adhesion.work: reason" becomes "BemSolver: adhesion.work: reason".
    std::string message;
    for (std::string line : error.problems()) {
      const std::string prefix = "interface.";
      if (const auto at = line.find(prefix); at != std::string::npos) line.erase(at, prefix.size());
      message += (message.empty() ? "" : "\n") + line;
    }
    throw Error(message);
  }
  return spec;
}

// The Python type's name of `value`, for messages.
std::string type_name(const py::handle& value) {
  return py::str(py::type::of(value).attr("__name__"));
}

// `hardness` as the scene's interface.hardness, read by the scene's reader (same check, same message, named
// hardness): a number H [Pa], or None (elastic). A bool or a string is refused by its type.
std::optional<Real> hardness_of(const py::object& hardness) {
  if (hardness.is_none()) return std::nullopt;
  const bool number = (py::isinstance<py::int_>(hardness) || py::isinstance<py::float_>(hardness) ||
                       py::hasattr(hardness, "__float__")) &&
                      !py::isinstance<py::bool_>(hardness) && !py::isinstance<py::str>(hardness);
  if (!number)
    throw Error("hardness: wrong type: expected a number H [Pa], got " + type_name(hardness) +
                "; accepted: a finite number > 0 [Pa], or None (elastic)");
  const toml::table document{
      {"interface", toml::table{{"hardness", py::cast<double>(py::float_(hardness))}}}};
  return read_python_interface(document).hardness;
}

// `adhesion` as the scene's interface.adhesion table ({"model": "dugdale", "work": w, "stress": σ0} or
// {"model": "exponential", "work": w, "range": ρ}), read by the scene's own reader (app/interface.cpp): the
// same checks and messages, each key named as adhesion.KEY. None: non-adhesive.
std::optional<AdhesionLaw> adhesion_of(const py::object& adhesion) {
  if (adhesion.is_none()) return std::nullopt;
  const std::string accepted =
      "a dict {\"model\": \"dugdale\", \"work\": W, \"stress\": SIGMA0} or {\"model\": \"exponential\", "
      "\"work\": W, \"range\": RHO}";
  if (!py::isinstance<py::dict>(adhesion))
    throw Error("adhesion: expected " + accepted + ", got " + type_name(adhesion));
  toml::table table;
  for (const auto& [name, value] : adhesion.cast<py::dict>()) {
    if (!py::isinstance<py::str>(name)) throw Error("adhesion: keys are strings; accepted: " + accepted);
    const std::string key = py::str(name);
    if (py::isinstance<py::str>(value))
      table.insert(key, value.cast<std::string>());
    else if ((py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) &&
             !py::isinstance<py::bool_>(value))
      table.insert(key, value.cast<double>());
    else
      throw Error("adhesion." + key + ": wrong type: expected a number (model: a string), got " +
                  type_name(value) + "; accepted: " + accepted);
  }
  const toml::table document{{"interface", toml::table{{"adhesion", table}}}};
  const InterfaceSpec spec = read_python_interface(document);
  validate_adhesion_law(*spec.adhesion, "adhesion");  // the solver's own check (always passes here)
  return spec.adhesion;
}

// The keyword arguments of BemSolver are the scene keys of the BEM method that a solver object takes
// (app/methods/bem_settings.cpp, the rows marked python), checked as a scene's: same defaults, same ranges.
BemSettings settings_of(const py::kwargs& keywords) {
  BemSettings settings = default_settings(bem_settings());
  std::vector<std::string> given;
  std::string accepted;
  for (const Setting<BemSettings>& row : bem_settings())
    if (row.python) accepted += (accepted.empty() ? "" : ", ") + row.key;
  for (const auto& [name, value] : keywords) {
    const std::string key = py::str(name);
    const Setting<BemSettings>* row = find_setting(bem_settings(), key);
    if (!row || !row->python)
      throw Error("BemSolver: unknown keyword " + key + "; accepted: " + accepted +
                  ", hardness, adhesion, threads");
    if (value.is_none()) continue;  // the default
    SettingValue typed;
    if (py::isinstance<py::bool_>(value))  // before int: a bool is an int in Python
      typed = value.cast<bool>();
    else if (py::isinstance<py::int_>(value))
      typed = value.cast<std::int64_t>();
    else if (py::isinstance<py::float_>(value))
      typed = value.cast<double>();
    else if (py::isinstance<py::str>(value))
      typed = value.cast<std::string>();
    else
      throw Error(key + ": wrong type: expected " + kind_text(row->kind) + ", got " +
                  std::string(py::str(py::type::of(value).attr("__name__"))));
    row->set(settings, checked_setting(spec_of(*row), typed, key));
    given.push_back(key);
  }
  finish_bem_settings(
      settings, given,
      [](const std::string& key, const std::string& reason, const std::string& accepted_values) {
        throw Error(key + ": " + reason + "; accepted: " + accepted_values);
      });
  return settings;
}

class PythonBemSolver {
 public:
  PythonBemSolver(const Surface& surface, Real modulus, std::optional<Real> hardness,
                  std::optional<AdhesionLaw> adhesion, int threads, const BemSettings& settings)
      : modulus_(modulus),
        adhesion_(adhesion),
        labeller_(Topology::for_surface(settings.connectivity == 8 ? Connectivity::eight : Connectivity::four,
                                        settings.periodic.value_or(surface.grid().periodic)),
                  checked_threads(threads)) {
    if (!(std::isfinite(modulus) && modulus > 0))
      throw Error("modulus: E* must be finite and > 0 Pa, got " + formats::format_real(modulus));
    options_ = settings.solver;
    options_.hardness = hardness;
    // Ctrl-C between iterations: a microsecond's check of Python's signal flag per iteration.
    options_.between_iterations = [] {
      py::gil_scoped_acquire locked;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    };
    // As the scene's preflight refuses it (app/methods/bem_method.cpp), in the same words.
    if (hardness && adhesion)
      throw Error(
          "adhesion: the BEM does not solve adhesion and a hardness together (the plastic cap and the "
          "attraction are two fixed points it does not couple); accepted: one of the two");
    const Surface solved = settings.periodic ? surface.with_periodic(*settings.periodic) : surface;
    if (adhesion)
      adhesive_ = std::make_unique<AdhesiveBemSolver>(
          solved, modulus, *adhesion,
          AdhesiveSolverOptions{.contact = options_, .method = settings.adhesive_method}, threads);
    else
      solver_ = std::make_unique<BemSolver>(solved, modulus, options_, threads);
    threads_ = threads;
    given_ = solved;
  }

  BemResult solve(Real mean_pressure) {
    std::lock_guard lock(mutex_);
    if (adhesive_) return adhesive_result(adhesive_->solve(mean_pressure));
    return result_of(solver_->solve(mean_pressure));
  }

  BemResult solve_for_separation(Real separation) {
    std::lock_guard lock(mutex_);
    if (adhesive_) return adhesive_result(adhesive_->solve_for_separation(separation));
    return result_of(solver_->solve_for_separation(separation));
  }

  // The load path in the listed order, up and down, as a scene's loads.path = "as listed" runs it
  // (app/serial_runner.cpp): a solver of its own from the surface as given (this one's warm start and state
  // untouched), keeping the plastic deformation from one step to the next when there is a hardness
  // (BemSolverOptions::keep_plastic_deformation; docs/solvers.md "Unloading and reloading").
  PythonLoadPath solve_path(const std::vector<Real>& loads) {
    std::lock_guard lock(mutex_);
    if (adhesive_)
      throw Error(
          "solve_path: the load path is the plastic BEM's (it keeps the plastic deformation); with adhesion "
          "use solve_loads or approach_retract; accepted: BemSolver(..., hardness=H) or no adhesion");
    BemSolverOptions options = options_;
    options.keep_plastic_deformation = options_.hardness.has_value();
    BemSolver path_solver(*given_, modulus_, options, threads_);
    PythonLoadPath path;
    for (const Real load : loads) {
      path.results.push_back(result_of(path_solver.solve(load * modulus_)));
      path.loads.push_back(load);
      {  // and between steps, as solve_loads does between loads
        py::gil_scoped_acquire locked;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      }
    }
    if (options_.hardness) path.residual_topography = path_solver.surface();
    return path;
  }

  // The approach-retract path (bem/adhesive_path.hpp), as `contactbench bem --approach-retract` runs it.
  PythonAdhesivePath approach_retract(Real start, Real turn, Index steps) {
    std::lock_guard lock(mutex_);
    if (!adhesive_)
      throw Error(
          "approach_retract: needs adhesion= (the path of a non-adhesive contact has no jumps); accepted: "
          "BemSolver(..., adhesion={...})");
    if (steps > 1000000)  // the CLI's cap: a path of millions of solves is a typo, not a study
      throw Error("approach_retract: steps " + std::to_string(steps) + " per leg; accepted: 2 to 1000000");
    const Grid& grid = adhesive_->surface().grid();
    return {contactbench::approach_retract(*adhesive_, {.start = start, .turn = turn, .steps = steps}),
            modulus_, grid.nx * grid.ny};
  }

  // As the scene's preflight refuses them (app/methods/method.cpp, check_hardness_above_loads), in its words
  // and before any solve: loads whose mean pressure load x E* is at or above the hardness (full plastic
  // contact, p = H everywhere, which has no solution to compute), each named by its position.
  void check_below_hardness(const std::vector<Real>& loads) const {
    if (!options_.hardness) return;
    std::string refused;
    for (std::size_t k = 0; k < loads.size(); ++k)
      if (loads[k] * modulus_ >= *options_.hardness)
        refused += (refused.empty() ? "" : ", ") + formats::format_real(loads[k]) + " (loads[" +
                   std::to_string(k) + "])";
    if (refused.empty()) return;
    throw Error(
        "hardness: the hardness " + formats::format_real(*options_.hardness) +
        " Pa is at or below the mean pressure P/A0 = load E* of the loads " + refused +
        ": full plastic contact, which has no solution to compute; accepted: loads below hardness/E* = " +
        formats::format_real(*options_.hardness / modulus_) + ", or a larger hardness");
  }

  Real modulus() const { return modulus_; }
  Index points() const {
    const Grid& grid = surface().grid();
    return grid.nx * grid.ny;
  }
  const BemSolverOptions& options() const { return options_; }
  const std::optional<AdhesionLaw>& adhesion() const { return adhesion_; }
  const Surface& surface() const { return adhesive_ ? adhesive_->surface() : solver_->surface(); }

 private:
  // The contact solution of the adhesive state (its repulsive pressure and net load), as the scene's runner
  // takes it (app/serial_runner.cpp), and what the attraction adds.
  BemResult adhesive_result(const AdhesiveSolution& state) {
    const ContactSolution solution = state.contact();
    return {solution,       contact_statistics(solution, labeller_), modulus_, state.adhesive(), points(),
            state.separated};
  }

  // A non-adhesive solution and its statistics, with the hardness for the plastic columns.
  BemResult result_of(const ContactSolution& solution) {
    return {
        solution,         contact_statistics(solution, labeller_), modulus_, std::nullopt, points(), false,
        options_.hardness};
  }

  Real modulus_;
  std::optional<AdhesionLaw> adhesion_;
  BemSolverOptions options_;
  Labeller labeller_;
  std::unique_ptr<BemSolver> solver_;            // without adhesion
  std::unique_ptr<AdhesiveBemSolver> adhesive_;  // with adhesion
  int threads_ = 1;
  std::optional<Surface> given_;  // as given (periodicity applied), where a load path starts
  std::mutex mutex_;              // one solve at a time: the GIL is released while it runs
};

// The solve runs without the GIL; a mutex (taken without the GIL, so no deadlock) keeps calls from two Python
// threads apart.
template <class Call>
BemResult unlocked(Call&& call) {
  py::gil_scoped_release release;
  return call();
}

// The Python type of a setting's values, for the typed signature line that help() and the type stubs read.
std::string python_type(SettingKind kind) {
  switch (kind) {
    case SettingKind::boolean:
      return "bool";
    case SettingKind::integer:
      return "int";
    case SettingKind::number:
      return "float";
    case SettingKind::choice:
    case SettingKind::text:
      return "str";
  }
  return "object";
}

// The signature and its keywords, from the declaration: each with its default and meaning. The first line is
// the typed signature (None stands for the declared default), which python/make_stubs.py copies into the
// stubs.
std::string bem_keywords_doc() {
  std::string text =
      "BemSolver(surface: Surface, modulus: float, *, hardness: Optional[float] = None, adhesion: "
      "Optional[Dict[str, Union[str, float]]] = None, threads: int = 1";
  std::string lines;
  for (const Setting<BemSettings>& row : bem_settings()) {
    if (!row.python) continue;
    const SettingSpec spec = spec_of(row);
    text += ", " + row.key + ": Optional[" + python_type(row.kind) + "] = None";
    lines += "  " + row.key + ": " + row.doc + (row.unit.empty() ? "" : " [" + row.unit + "]") +
             "; default " + spec.default_text + "; accepted " +
             (row.accepted.empty() ? kind_text(row.kind) : row.accepted) + "\n";
  }
  return text +
         ")\n  modulus: E* [Pa]; hardness: the interface's perfectly plastic cap H [Pa] (None: elastic), as "
         "the "
         "scene's interface.hardness and the CLI's --hardness; "
         "adhesion: the interface's attraction (None: non-adhesive), {\"model\": \"dugdale\", \"work\": w "
         "[J/m^2], \"stress\": sigma0 [Pa]} or {\"model\": \"exponential\", \"work\": w, \"range\": rho "
         "[m]}, "
         "as the scene's interface.adhesion; threads: for the FFTs.\n" +
         lines;
}

// One load in one unit: `load` P/(E* A0) (also by position), or `mean_pressure` P/A0 [Pa] by keyword only;
// exactly one of them, finite and >= 0. Returns the mean pressure [Pa] the C++ solver takes.
Real mean_pressure_of(std::optional<Real> load, std::optional<Real> mean_pressure, Real modulus) {
  if (load.has_value() == mean_pressure.has_value())
    throw Error(
        "solve: give exactly one of load (P/(E* A0), also by position) and mean_pressure= (P/A0 [Pa]), got " +
        std::string(load ? "both" : "neither"));
  const Real value = load ? *load : *mean_pressure;
  if (!(std::isfinite(value) && value >= 0))
    throw Error(std::string(load ? "load: P/(E* A0)" : "mean_pressure: P/A0 [Pa]") +
                " must be finite and >= 0, got " + formats::format_real(value));
  return load ? *load * modulus : *mean_pressure;
}

}  // namespace

void register_bem(py::module_& m) {
  static const std::string solver_doc =
      "The boundary-element ground truth (Polonsky & Keer 1999; docs/theory.md section 6): a rigid flat on "
      "the "
      "rough surface, elastic half-space of contact modulus E* [Pa]. Successive solves are warm-started: "
      "solve "
      "increasing loads in order.\n\n" +
      bem_keywords_doc();
  py::class_<BemResult>(m, "BemResult",
                        "One boundary-element solution: the fields as read-only (ny, nx) float64 views (no "
                        "copy; rows = y like the surface's heights) and what they say about the contact.")
      .def_property_readonly(
          "pressure",
          [](const py::object& self) {
            return view_of(self.cast<const BemResult&>().solution.pressure, self);
          },
          "contact pressure p [Pa], (ny, nx)")
      .def_property_readonly(
          "gap",
          [](const py::object& self) { return view_of(self.cast<const BemResult&>().solution.gap, self); },
          "gap g [m], (ny, nx): 0 on the contact set")
      .def_property_readonly(
          "mean_pressure", [](const BemResult& r) { return r.solution.mean_pressure; },
          "P/A0 [Pa]: prescribed (solve) or found (solve_for_separation)")
      .def_property_readonly(
          "load", [](const BemResult& r) { return r.solution.mean_pressure / r.modulus; }, "P/(E* A0) [-]")
      .def_property_readonly(
          "separation", [](const BemResult& r) { return r.solution.separation; },
          "d: the flat's height above the mean plane of the heights [m]")
      .def_property_readonly(
          "area_fraction", [](const BemResult& r) { return r.statistics.area_fraction; },
          "contact nodes / all nodes [-]")
      .def_property_readonly(
          "area_fraction_corrected", [](const BemResult& r) { return r.statistics.area_fraction_corrected; },
          "A/A0 less the perimeter term of Yastrebov, Anciaux and Molinari 2017 [-] (docs/theory.md section "
          "6)")
      .def_property_readonly(
          "spots", [](const BemResult& r) { return r.statistics.spots; },
          "connected contact regions (the solver's connectivity)")
      .def_property_readonly(
          "mean_gap", [](const BemResult& r) { return r.statistics.mean_gap; }, "mean gap over all nodes [m]")
      .def_property_readonly(
          "max_pressure", [](const BemResult& r) { return r.statistics.max_pressure; },
          "largest pressure [Pa]")
      .def_property_readonly(
          "contact_points", [](const BemResult& r) { return r.solution.contact_points; },
          "nodes with p > 0 (plastic ones included)")
      .def_property_readonly(
          "plastic_points", [](const BemResult& r) { return r.solution.plastic_points; },
          "nodes at p = hardness (0 without a hardness)")
      .def_property_readonly(
          "plastic_area_fraction",
          [](const BemResult& r) -> std::optional<Real> {
            if (!r.hardness) return std::nullopt;
            return plastic_area_fraction(r);
          },
          "with a hardness: nodes at p = H / all nodes [-], the CLI's plastic_area_fraction; None without")
      .def_property_readonly(
          "plastic_load_fraction",
          [](const BemResult& r) -> std::optional<Real> {
            if (!r.hardness) return std::nullopt;
            return plastic_load_fraction(r);
          },
          "with a hardness: H x plastic area / P, the share of the load the plastic nodes carry [-] (the "
          "CLI's "
          "plastic_load_fraction; docs/theory.md section 6.7); None without")
      .def_property_readonly(
          "iterations", [](const BemResult& r) { return r.solution.iterations; },
          "conjugate-gradient iterations (with a hardness: of every solve of the search)")
      .def_property_readonly(
          "change", [](const BemResult& r) { return r.solution.change; },
          "the last relative change of the pressure [-]")
      .def_property_readonly(
          "residual", [](const BemResult& r) { return r.solution.residual; },
          "max |gap| on the contact set / height range [-]")
      .def_property_readonly(
          "converged", [](const BemResult& r) { return r.solution.converged; },
          "False when the iteration cap was reached")
      .def_property_readonly(
          "seconds", [](const BemResult& r) { return r.solution.seconds; }, "wall time [s]")
      // What an attraction adds (the scene's and the CLI's adhesive columns); None without an adhesion.
      .def_property_readonly(
          "adhesive_load",
          [](const BemResult& r) -> std::optional<Real> {
            if (!r.adhesive) return std::nullopt;
            return r.adhesive->adhesive_pressure / r.modulus;
          },
          "the attraction's pull mean(a)/E* in the loads' unit [-] (the repulsive load is load + it); None "
          "without adhesion")
      .def_property_readonly(
          "attractive_fraction",
          [](const BemResult& r) -> std::optional<Real> {
            if (!r.adhesive) return std::nullopt;
            return static_cast<Real>(r.adhesive->attractive_points) / static_cast<Real>(r.points);
          },
          "nodes out of contact pulled by the attraction / all nodes [-]; None without adhesion")
      .def_property_readonly(
          "zone_pixels",
          [](const BemResult& r) -> std::optional<Real> {
            if (!r.adhesive) return std::nullopt;
            return r.adhesive->zone_pixels;
          },
          "the attractive zone's width at the contact edge [pixels] (below about 5 the law is not resolved, "
          "docs/solvers.md \"Adhesion\"); None without adhesion")
      .def_property_readonly(
          "outer_iterations",
          [](const BemResult& r) -> std::optional<Index> {
            if (!r.adhesive) return std::nullopt;
            return r.adhesive->outer_iterations;
          },
          "contact solves of the fixed point on the attraction; None without adhesion")
      .def_property_readonly(
          "separated", [](const BemResult& r) { return r.separated; },
          "with adhesion, load control: no state in contact carries the load (below the pull-off force)");

  using State = AdhesivePathState;
  using Path = PythonAdhesivePath;
  py::class_<PythonAdhesivePath>(
      m, "AdhesivePath",
      "An approach-retract path of the adhesive BEM (BemSolver.approach_retract; bem/adhesive_path.hpp): one "
      "entry per state in path order (the approach leg, then the retract leg), as the columns of "
      "`contactbench "
      "bem --approach-retract`, each a new numpy array, and the path's summary.")
      .def_property_readonly(
          "approaching",
          [](const Path& p) {
            return path_column<bool>(p, [](const State& s, const Path&) { return s.approaching; });
          },
          "True on the approach leg, False on the retract leg")
      .def_property_readonly(
          "separation",
          [](const Path& p) {
            return path_column<Real>(p, [](const State& s, const Path&) { return s.separation; });
          },
          "d: the flat's height above the mean plane of the heights [m]")
      .def_property_readonly(
          "load",
          [](const Path& p) {
            return path_column<Real>(
                p, [](const State& s, const Path& q) { return s.mean_pressure / q.modulus; });
          },
          "net P/(E* A0) [-], negative when tensile")
      .def_property_readonly(
          "adhesive_load",
          [](const Path& p) {
            return path_column<Real>(
                p, [](const State& s, const Path& q) { return s.adhesive_pressure / q.modulus; });
          },
          "the attraction's pull mean(a)/E* [-]")
      .def_property_readonly(
          "contact_fraction",
          [](const Path& p) {
            return path_column<Real>(p, [](const State& s, const Path& q) {
              return static_cast<Real>(s.contact_points) / static_cast<Real>(q.points);
            });
          },
          "contact nodes / all nodes [-]")
      .def_property_readonly(
          "attractive_fraction",
          [](const Path& p) {
            return path_column<Real>(p, [](const State& s, const Path& q) {
              return static_cast<Real>(s.attractive_points) / static_cast<Real>(q.points);
            });
          },
          "nodes out of contact pulled by the attraction / all nodes [-]")
      .def_property_readonly(
          "mean_gap",
          [](const Path& p) {
            return path_column<Real>(p, [](const State& s, const Path&) { return s.mean_gap; });
          },
          "[m]")
      .def_property_readonly(
          "energy",
          [](const Path& p) {
            return path_column<Real>(p, [](const State& s, const Path&) { return s.energy; });
          },
          "U per nominal area [J/m^2] (docs/theory.md 10.7)")
      .def_property_readonly(
          "iterations",
          [](const Path& p) {
            return path_column<Index>(p, [](const State& s, const Path&) { return s.iterations; });
          },
          "contact-solver iterations of each state")
      .def_property_readonly(
          "state_converged",
          [](const Path& p) {
            return path_column<bool>(p, [](const State& s, const Path&) { return s.converged; });
          },
          "whether each state converged")
      .def_property_readonly(
          "pull_off_load", [](const Path& p) { return p.path.pull_off_pressure / p.modulus; },
          "the most tensile net P/(E* A0) on the retract leg [-] (<= 0)")
      .def_property_readonly(
          "pull_off_separation", [](const Path& p) { return p.path.pull_off_separation; },
          "where it occurs [m]")
      .def_property_readonly(
          "pull_off_located", [](const Path& p) { return p.path.pull_off_located; },
          "True when the pull-off was located between two samples of the retract branch (a golden-section "
          "search on the separation, docs/theory.md 10.7), False when it is the least sample (not bracketed)")
      .def_property_readonly(
          "pull_off_solves", [](const Path& p) { return p.path.pull_off_solves; },
          "the solves the location took (not among the states)")
      .def_property_readonly(
          "cycle_work", [](const Path& p) { return p.path.cycle_work; },
          "-oint P/A0 dd over the path [J/m^2] (trapezoid rule)")
      .def_property_readonly(
          "released_energy", [](const Path& p) { return p.path.released_energy; },
          "summed over the jumps [J/m^2]")
      .def_property_readonly(
          "jumps",
          [](const Path& p) {
            py::list jumps;
            for (const AdhesiveJump& j : p.path.jumps) {
              py::dict d;
              d["into_contact"] = j.into_contact;
              d["after"] = j.after;
              d["separation_before"] = j.separation_before;
              d["separation_after"] = j.separation_after;
              d["load_before"] = j.mean_pressure_before / p.modulus;
              d["load_after"] = j.mean_pressure_after / p.modulus;
              d["contact_fraction_before"] =
                  static_cast<Real>(j.contact_points_before) / static_cast<Real>(p.points);
              d["contact_fraction_after"] =
                  static_cast<Real>(j.contact_points_after) / static_cast<Real>(p.points);
              d["released_energy"] = j.released_energy;
              jumps.append(d);
            }
            return jumps;
          },
          "the jumps into (approach) and out of (retract) contact, each a dict: into_contact, after (the "
          "index "
          "of the state after it), separation_before/after [m], load_before/after, "
          "contact_fraction_before/after, released_energy [J/m^2]")
      .def_property_readonly(
          "converged", [](const Path& p) { return p.path.converged; }, "every state converged");

  using LoadPath = PythonLoadPath;
  // One column of the path's steps as a new numpy array.
  const auto steps_column = [](const LoadPath& p, auto value) {
    std::vector<decltype(value(p.results.front(), Real{}))> column;
    for (std::size_t k = 0; k < p.results.size(); ++k)
      column.push_back(value(p.results[k], p.loads[k]));
    return py::array(py::cast(column));
  };
  py::class_<PythonLoadPath>(
      m, "LoadPath",
      "A load path up and down (BemSolver.solve_path), as a scene's loads.path = \"as listed\" solves it: "
      "one entry per step in the path's order, as the columns of the scene's <label>_path.csv (each a new "
      "numpy array), the BemResult of each step, and the residual topography.")
      .def_property_readonly(
          "results", [](const LoadPath& p) { return p.results; }, "the BemResult of each step, in order")
      .def_property_readonly(
          "load",
          [=](const LoadPath& p) { return steps_column(p, [](const BemResult&, Real l) { return l; }); },
          "P/(E* A0) of each step [-], as listed")
      .def_property_readonly(
          "direction",
          [](const LoadPath& p) {
            std::vector<int> column;
            for (std::size_t k = 0; k < p.loads.size(); ++k) {
              const Real before = k == 0 ? 0 : p.loads[k - 1];  // from zero load for the first
              column.push_back(p.loads[k] > before ? 1 : p.loads[k] < before ? -1 : 0);
            }
            return py::array(py::cast(column));
          },
          "+1 loading, -1 unloading, 0 the same load again (from the step before; from zero for the first)")
      .def_property_readonly(
          "area_fraction",
          [=](const LoadPath& p) {
            return steps_column(p, [](const BemResult& r, Real) { return r.statistics.area_fraction; });
          },
          "contact nodes / all nodes [-] (the path CSV's area_fraction_nodes)")
      .def_property_readonly(
          "area_fraction_corrected",
          [=](const LoadPath& p) {
            return steps_column(
                p, [](const BemResult& r, Real) { return r.statistics.area_fraction_corrected; });
          },
          "A/A0 less the perimeter term [-] (the path CSV's area_fraction, the scene's default compared "
          "area)")
      .def_property_readonly(
          "plastic_area_fraction",
          [=](const LoadPath& p) {
            return steps_column(
                p, [](const BemResult& r, Real) { return r.hardness ? plastic_area_fraction(r) : Real{0}; });
          },
          "nodes at p = H / all nodes [-] (0 without a hardness)")
      .def_property_readonly(
          "plastic_load_fraction",
          [=](const LoadPath& p) {
            return steps_column(
                p, [](const BemResult& r, Real) { return r.hardness ? plastic_load_fraction(r) : Real{0}; });
          },
          "H x plastic area / P [-] (0 without a hardness)")
      .def_property_readonly(
          "separation",
          [=](const LoadPath& p) {
            return steps_column(p, [](const BemResult& r, Real) { return r.solution.separation; });
          },
          "d: the flat's height above the mean plane of the given heights [m]")
      .def_property_readonly(
          "iterations",
          [=](const LoadPath& p) {
            return steps_column(p, [](const BemResult& r, Real) { return r.solution.iterations; });
          },
          "solver iterations of each step")
      .def_property_readonly(
          "state_converged",
          [=](const LoadPath& p) {
            return steps_column(p, [](const BemResult& r, Real) { return r.solution.converged; });
          },
          "whether each step converged")
      .def_property_readonly(
          "converged",
          [](const LoadPath& p) {
            return std::all_of(p.results.begin(), p.results.end(),
                               [](const BemResult& r) { return r.solution.converged; });
          },
          "every step converged")
      .def_property_readonly(
          "residual_topography", [](const LoadPath& p) { return p.residual_topography; },
          "with a hardness: the surface as the path left it, lowered where it flowed (heights from the given "
          "surface's mean plane; what the scene's residual_topography file holds); None without");

  py::class_<PythonBemSolver>(m, "BemSolver", solver_doc.c_str())
      .def(py::init([](const Surface& surface, Real modulus, const py::object& hardness,
                       const py::object& adhesion, int threads, const py::kwargs& keywords) {
             return std::make_unique<PythonBemSolver>(surface, modulus, hardness_of(hardness),
                                                      adhesion_of(adhesion), threads, settings_of(keywords));
           }),
           py::arg("surface"), py::arg("modulus"), py::kw_only(), py::arg("hardness") = py::none(),
           py::arg("adhesion") = py::none(), py::arg("threads") = 1)
      .def(
          "solve",
          [](PythonBemSolver& s, std::optional<Real> load, std::optional<Real> mean_pressure) {
            const Real pressure = mean_pressure_of(load, mean_pressure, s.modulus());
            s.check_below_hardness({pressure / s.modulus()});
            return unlocked([&] { return s.solve(pressure); });
          },
          py::arg("load") = py::none(), py::kw_only(), py::arg("mean_pressure") = py::none(),
          "Solves one load, warm-started from the previous solve: load = P/(E* A0) [-] (by position or "
          "keyword, as in solve_loads, scenes and the CLI), or mean_pressure = P/A0 [Pa] (by keyword only); "
          "exactly one. Releases the GIL; Ctrl-C stops it between iterations (KeyboardInterrupt).")
      .def(
          "solve_for_separation",
          [](PythonBemSolver& s, Real separation) {
            return unlocked([&] { return s.solve_for_separation(separation); });
          },
          py::arg("separation"),
          "Solves with the flat at height d [m] above the mean plane of the heights, the load unknown "
          "(result.mean_pressure). Releases the GIL; Ctrl-C stops it between iterations.")
      .def(
          "solve_loads",
          [](PythonBemSolver& s, const std::vector<Real>& loads) {
            for (std::size_t k = 0; k < loads.size(); ++k)
              if (!(std::isfinite(loads[k]) && loads[k] >= 0 && (k == 0 || loads[k] >= loads[k - 1])))
                throw Error("loads: every load P/(E* A0) must be finite, >= 0 and ascending; load " +
                            std::to_string(k) + " is " + formats::format_real(loads[k]));
            s.check_below_hardness(loads);
            std::vector<BemResult> results;
            for (const Real load : loads) {
              results.push_back(unlocked([&] { return s.solve(load * s.modulus()); }));
              check_signals();  // and between loads
            }
            return results;  // a list of BemResult
          },
          py::arg("loads"),
          "Solves each load P/(E* A0) (ascending), like `contactbench bem --loads`: a list of BemResult. "
          "Ctrl-C "
          "stops it between iterations (KeyboardInterrupt).")
      .def(
          "solve_path",
          [](PythonBemSolver& s, const std::vector<Real>& loads) {
            if (loads.empty()) throw Error("loads: the path needs at least one load P/(E* A0)");
            for (std::size_t k = 0; k < loads.size(); ++k)
              if (!(std::isfinite(loads[k]) && loads[k] > 0))
                throw Error(
                    "loads: every load P/(E* A0) of a path must be finite and > 0 (any order); load " +
                    std::to_string(k) + " is " + formats::format_real(loads[k]));
            s.check_below_hardness(loads);
            py::gil_scoped_release release;
            return s.solve_path(loads);
          },
          py::arg("loads"),
          "Solves the loads P/(E* A0) in the order listed, up and down, as a scene's loads.path = \"as "
          "listed\" does: from the surface as given (a solver of its own: this one's warm start is left as "
          "it "
          "is), and with a hardness keeping the plastic deformation from one step to the next (unloading is "
          "the elastic response of the deformed surface, reloading gives the loaded state again): a "
          "LoadPath. "
          "Releases the GIL; Ctrl-C stops it between iterations (KeyboardInterrupt).")
      .def(
          "approach_retract",
          [](PythonBemSolver& s, Real start, Real turn, Index steps) {
            py::gil_scoped_release release;
            return s.approach_retract(start, turn, steps);
          },
          py::arg("start"), py::arg("turn"), py::arg("steps"),
          "With adhesion: the flat from separation `start` [m] down to `turn` (< start) in `steps` (>= 2) "
          "equal "
          "steps and back, each solve from the last state (a fresh approach first), like `contactbench bem "
          "--approach-retract START,TURN,STEPS`: an AdhesivePath. Releases the GIL; Ctrl-C stops it between "
          "iterations.")
      .def_property_readonly("modulus", &PythonBemSolver::modulus, "E* [Pa]")
      .def_property_readonly(
          "tolerance", [](const PythonBemSolver& s) { return s.options().tolerance; },
          "on the relative change of the pressure [-]")
      .def_property_readonly(
          "hardness", [](const PythonBemSolver& s) { return s.options().hardness; }, "H [Pa] or None")
      .def_property_readonly(
          "adhesion",
          [](const PythonBemSolver& s) -> std::optional<py::dict> {
            const std::optional<AdhesionLaw>& law = s.adhesion();
            if (!law) return std::nullopt;
            py::dict d;
            d["model"] = std::string(adhesion_model_name(law->model));
            d["work"] = law->work;
            if (law->model == AdhesionModel::dugdale)
              d["stress"] = law->stress;
            else
              d["range"] = law->range;
            return d;
          },
          "the adhesion law as given ({\"model\": ..., \"work\": ..., ...}) or None")
      .def_property_readonly(
          "precision",
          [](const PythonBemSolver& s) { return s.options().single_precision ? "single" : "double"; },
          "\"double\" or \"single\"")
      .def_property_readonly(
          "solver", [](const PythonBemSolver& s) { return std::string(solver_name(s.options().solver)); },
          "the BEM iteration")
      .def_property_readonly("surface", &PythonBemSolver::surface,
                             "the surface solved (centred: mean removed)");
}

}  // namespace contactbench::python
