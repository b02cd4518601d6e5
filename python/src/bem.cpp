// The boundary-element ground truth as a solver object (bem/polonsky_keer.hpp, bem/contact_statistics.hpp,
// docs/theory.md section 6). Solves release the GIL. Ctrl-C is honoured between iterations: the solver's
// between_iterations hook takes the GIL, lets Python run its signal handlers and abandons the solve with
// KeyboardInterrupt (the solver then starts its next solve afresh).
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "bindings.hpp"
#include "contactbench/bem/contact_statistics.hpp"
#include "contactbench/bem/polonsky_keer.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench::python {

namespace {

// The CLI's default tolerance (`contactbench bem`), so that the same call gives the CLI's numbers.
constexpr Real kDefaultTolerance = 1e-8;

struct BemResult {
  ContactSolution solution;
  ContactStatistics statistics;
  Real modulus = 0;  // E* [Pa]
};

class BemSolver {
 public:
  BemSolver(const Surface& surface, Real modulus, std::optional<Real> tolerance, Index max_iterations,
            std::optional<Real> hardness, bool single_precision, std::optional<bool> periodic,
            int connectivity, const std::string& solver, int threads)
      : modulus_(modulus),
        labeller_(Topology::for_surface(connectivity == 8 ? Connectivity::eight : Connectivity::four,
                                        periodic.value_or(surface.grid().periodic)),
                  checked_threads(threads)) {
    if (!(std::isfinite(modulus) && modulus > 0))
      throw Error("modulus: E* must be finite and > 0 Pa, got " + std::to_string(modulus));
    if (connectivity != 4 && connectivity != 8)
      throw Error("connectivity: accepted values are 4 or 8, got " + std::to_string(connectivity));
    options_ = {
        .tolerance = tolerance.value_or(single_precision ? kSinglePrecisionTolerance : kDefaultTolerance),
        .max_iterations = max_iterations,
        .hardness = hardness,
        .single_precision = single_precision,
        .solver = solver_kind(solver, "solver")};
    // Ctrl-C between iterations: a microsecond's check of Python's signal flag per iteration.
    options_.between_iterations = [] {
      py::gil_scoped_acquire locked;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    };  // bem/solver_registry.hpp: unknown names list the known
    const Surface solved = periodic ? surface.with_periodic(*periodic) : surface;
    solver_ = std::make_unique<PolonskyKeer>(solved, modulus, options_, threads);
  }

  BemResult solve(Real mean_pressure) {
    std::lock_guard lock(mutex_);
    const ContactSolution& solution = solver_->solve(mean_pressure);
    return {solution, contact_statistics(solution, labeller_), modulus_};
  }

  BemResult solve_for_separation(Real separation) {
    std::lock_guard lock(mutex_);
    const ContactSolution& solution = solver_->solve_for_separation(separation);
    return {solution, contact_statistics(solution, labeller_), modulus_};
  }

  Real modulus() const { return modulus_; }
  const PolonskyKeerOptions& options() const { return options_; }
  const Surface& surface() const { return solver_->surface(); }

 private:
  Real modulus_;
  PolonskyKeerOptions options_;
  Labeller labeller_;
  std::unique_ptr<PolonskyKeer> solver_;
  std::mutex mutex_;  // one solve at a time: the GIL is released while it runs
};

// The solve runs without the GIL; a mutex (taken without the GIL, so no deadlock) keeps calls from two Python
// threads apart.
template <class Call>
BemResult unlocked(Call&& call) {
  py::gil_scoped_release release;
  return call();
}

}  // namespace

void register_bem(py::module_& m) {
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
          "seconds", [](const BemResult& r) { return r.solution.seconds; }, "wall time [s]");

  py::class_<BemSolver>(
      m, "BemSolver",
      "The boundary-element ground truth (Polonsky & Keer 1999; docs/theory.md section 6): a rigid flat on "
      "the "
      "rough surface, elastic half-space of contact modulus E* [Pa]. Successive solves are warm-started: "
      "solve "
      "increasing loads in order.\n\n"
      "BemSolver(surface, modulus, *, tolerance=None, max_iterations=20000, hardness=None, "
      "single_precision=False, periodic=None, connectivity=4, threads=1)\n"
      "  modulus: E* [Pa]; tolerance: on the relative change of the pressure (default 1e-8 as the CLI, 1e-6 "
      "with single_precision); hardness: perfectly plastic cap H [Pa]; single_precision: the CLI's --float; "
      "periodic: the half-space (default: the surface's own periodicity); connectivity 4 or 8 for the spot "
      "count; threads for the FFTs.")
      .def(py::init<const Surface&, Real, std::optional<Real>, Index, std::optional<Real>, bool,
                    std::optional<bool>, int, const std::string&, int>(),
           py::arg("surface"), py::arg("modulus"), py::kw_only(), py::arg("tolerance") = py::none(),
           py::arg("max_iterations") = 20000, py::arg("hardness") = py::none(),
           py::arg("single_precision") = false, py::arg("periodic") = py::none(), py::arg("connectivity") = 4,
           py::arg("solver") = std::string(solver_name(kDefaultSolver)), py::arg("threads") = 1)
      .def(
          "solve",
          [](BemSolver& s, Real mean_pressure) { return unlocked([&] { return s.solve(mean_pressure); }); },
          py::arg("mean_pressure"),
          "Solves for the mean pressure P/A0 [Pa] (>= 0), warm-started from the previous solve. Releases the "
          "GIL; Ctrl-C stops it between iterations (KeyboardInterrupt).")
      .def(
          "solve_for_separation",
          [](BemSolver& s, Real separation) {
            return unlocked([&] { return s.solve_for_separation(separation); });
          },
          py::arg("separation"),
          "Solves with the flat at height d [m] above the mean plane of the heights, the load unknown "
          "(result.mean_pressure). Releases the GIL; Ctrl-C stops it between iterations.")
      .def(
          "solve_loads",
          [](BemSolver& s, const std::vector<Real>& loads) {
            for (std::size_t k = 0; k < loads.size(); ++k)
              if (!(std::isfinite(loads[k]) && loads[k] >= 0 && (k == 0 || loads[k] >= loads[k - 1])))
                throw Error("loads: every load P/(E* A0) must be finite, >= 0 and ascending; load " +
                            std::to_string(k) + " is " + std::to_string(loads[k]));
            py::list results;
            for (const Real load : loads) {
              results.append(unlocked([&] { return s.solve(load * s.modulus()); }));
              check_signals();  // and between loads
            }
            return results;
          },
          py::arg("loads"),
          "Solves each load P/(E* A0) (ascending), like `contactbench bem --loads`: a list of BemResult. "
          "Ctrl-C "
          "stops it between iterations (KeyboardInterrupt).")
      .def_property_readonly("modulus", &BemSolver::modulus, "E* [Pa]")
      .def_property_readonly(
          "tolerance", [](const BemSolver& s) { return s.options().tolerance; },
          "on the relative change of the pressure [-]")
      .def_property_readonly(
          "hardness", [](const BemSolver& s) { return s.options().hardness; }, "H [Pa] or None")
      .def_property_readonly("single_precision",
                             [](const BemSolver& s) { return s.options().single_precision; })
      .def_property_readonly("surface", &BemSolver::surface, "the surface solved (centred: mean removed)");
}

}  // namespace contactbench::python
