// The boundary-element ground truth as a solver object (bem/bem_solver.hpp, bem/contact_statistics.hpp,
// docs/theory.md section 6). Solves release the GIL. Ctrl-C is honoured between iterations: the solver's
// between_iterations hook takes the GIL, lets Python run its signal handlers and abandons the solve with
// KeyboardInterrupt (the solver then starts its next solve afresh). With `adhesion`, the adhesive solver
// (bem/adhesive_solver.hpp) around the same contact solver, as `contactbench bem --adhesion` runs it.
#include <pybind11/stl.h>

#include <toml++/toml.h>

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

// `adhesion` as the scene's interface.adhesion table ({"model": "dugdale", "work": w, "stress": σ0} or
// {"model": "exponential", "work": w, "range": ρ}), read by the scene's own reader (app/interface.cpp): the
// same checks and messages, each key named as adhesion.KEY. None: non-adhesive.
std::optional<AdhesionLaw> adhesion_of(const py::object& adhesion) {
  if (adhesion.is_none()) return std::nullopt;
  const std::string accepted =
      "a dict {\"model\": \"dugdale\", \"work\": W, \"stress\": SIGMA0} or {\"model\": \"exponential\", "
      "\"work\": W, \"range\": RHO}";
  if (!py::isinstance<py::dict>(adhesion))
    throw Error("adhesion: expected " + accepted + ", got " +
                std::string(py::str(py::type::of(adhesion).attr("__name__"))));
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
                  std::string(py::str(py::type::of(value).attr("__name__"))) + "; accepted: " + accepted);
  }
  const toml::table document{{"interface", toml::table{{"adhesion", table}}}};
  Problems problems("BemSolver");
  const InterfaceSpec spec = read_interface(Section(document, "", problems, true));
  try {
    problems.throw_if_any();
  } catch (const SceneError& error) {
    // "BemSolver: interface.adhesion.work: reason": the key as the caller wrote it.
    std::string message;
    for (std::string line : error.problems()) {
      if (const auto at = line.find("interface.adhesion"); at != std::string::npos) line.erase(at, 10);
      message += (message.empty() ? "" : "\n") + line;
    }
    throw Error(message);
  }
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
      adhesive_ = std::make_unique<AdhesiveBemSolver>(solved, modulus, *adhesion,
                                                      AdhesiveSolverOptions{.contact = options_}, threads);
    else
      solver_ = std::make_unique<BemSolver>(solved, modulus, options_, threads);
  }

  BemResult solve(Real mean_pressure) {
    std::lock_guard lock(mutex_);
    if (adhesive_) return adhesive_result(adhesive_->solve(mean_pressure));
    const ContactSolution& solution = solver_->solve(mean_pressure);
    return {solution, contact_statistics(solution, labeller_), modulus_, std::nullopt, 0, false};
  }

  BemResult solve_for_separation(Real separation) {
    std::lock_guard lock(mutex_);
    if (adhesive_) return adhesive_result(adhesive_->solve_for_separation(separation));
    const ContactSolution& solution = solver_->solve_for_separation(separation);
    return {solution, contact_statistics(solution, labeller_), modulus_, std::nullopt, 0, false};
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

  Real modulus() const { return modulus_; }
  const BemSolverOptions& options() const { return options_; }
  const std::optional<AdhesionLaw>& adhesion() const { return adhesion_; }
  const Surface& surface() const { return adhesive_ ? adhesive_->surface() : solver_->surface(); }

 private:
  // The contact solution of the adhesive state (its repulsive pressure and net load), as the scene's runner
  // takes it (app/serial_runner.cpp), and what the attraction adds.
  BemResult adhesive_result(const AdhesiveSolution& state) {
    const ContactSolution solution = state.contact();
    const Grid& grid = adhesive_->surface().grid();
    return {solution,          contact_statistics(solution, labeller_),
            modulus_,          state.adhesive(),
            grid.nx * grid.ny, state.separated};
  }

  Real modulus_;
  std::optional<AdhesionLaw> adhesion_;
  BemSolverOptions options_;
  Labeller labeller_;
  std::unique_ptr<BemSolver> solver_;            // without adhesion
  std::unique_ptr<AdhesiveBemSolver> adhesive_;  // with adhesion
  std::mutex mutex_;                             // one solve at a time: the GIL is released while it runs
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
         ")\n  modulus: E* [Pa]; hardness: the interface's perfectly plastic cap H [Pa] (None: elastic); "
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

  py::class_<PythonBemSolver>(m, "BemSolver", solver_doc.c_str())
      .def(py::init([](const Surface& surface, Real modulus, std::optional<Real> hardness,
                       const py::object& adhesion, int threads, const py::kwargs& keywords) {
             return std::make_unique<PythonBemSolver>(surface, modulus, hardness, adhesion_of(adhesion),
                                                      threads, settings_of(keywords));
           }),
           py::arg("surface"), py::arg("modulus"), py::kw_only(), py::arg("hardness") = py::none(),
           py::arg("adhesion") = py::none(), py::arg("threads") = 1)
      .def(
          "solve",
          [](PythonBemSolver& s, std::optional<Real> load, std::optional<Real> mean_pressure) {
            const Real pressure = mean_pressure_of(load, mean_pressure, s.modulus());
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
