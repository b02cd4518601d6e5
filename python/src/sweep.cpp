// The geometric sweep A_c(z), N(z) (core/sweep.hpp, docs/theory.md section 3) and the load-area curve that
// every method returns (core/load_area_curve.hpp).
#include <pybind11/stl.h>

#include <optional>

#include "bindings.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/sweep.hpp"

namespace contactbench::python {

namespace {

// levels = "exact" | "paper" | an integer count (uniform), as in a scene file.
SweepLevels parse_levels(const py::object& levels) {
  if (py::isinstance<py::str>(levels)) {
    if (const auto named = SweepLevels::named(levels.cast<std::string>())) return *named;
  } else if (py::isinstance<py::int_>(levels) && !py::isinstance<py::bool_>(levels)) {
    if (const auto counted = SweepLevels::counted(levels.cast<std::int64_t>())) return *counted;
  }
  throw Error("levels: accepted values are " + std::string(SweepLevels::kAccepted) + ", got " +
              std::string(py::repr(levels)));
}

Topology topology(int connectivity, bool periodic) {
  const std::optional<Connectivity> neighbours = connectivity_of(connectivity);
  if (!neighbours)
    throw Error("connectivity: accepted values are " + std::string(kConnectivityAccepted) + ", got " +
                std::to_string(connectivity));
  return Topology::for_surface(*neighbours, periodic);
}

}  // namespace

void register_sweep(py::module_& m) {
  py::class_<SweepCurve>(
      m, "SweepCurve",
      "A_c(z) and N(z) of {h > z} at descending levels z (docs/theory.md section 3). Arrays "
      "are read-only views (no copy).")
      .def_property_readonly(
          "z", [](const py::object& self) { return view_of(self.cast<const SweepCurve&>().z, self); },
          "levels [m], descending")
      .def_property_readonly(
          "area_fraction",
          [](const py::object& self) { return view_of(self.cast<const SweepCurve&>().area_fraction, self); },
          "bearing area A_c(z)/A0 [-]")
      .def_property_readonly(
          "points",
          [](const py::object& self) { return view_of(self.cast<const SweepCurve&>().points, self); },
          "points with h > z (int64)")
      .def_property_readonly(
          "spots", [](const py::object& self) { return view_of(self.cast<const SweepCurve&>().spots, self); },
          "N(z): connected components of {h > z} (int64)")
      .def_readonly("nominal_area", &SweepCurve::nominal_area, "A0 = lx ly [m^2]")
      .def_property_readonly(
          "topology", [](const SweepCurve& s) { return describe(s.topology); },
          "connectivity and periodicity used, in words")
      .def("__len__", [](const SweepCurve& s) { return s.z.size(); });

  m.def(
      "sweep",
      [](const Surface& surface, const py::object& levels, int connectivity, std::optional<bool> periodic,
         int threads) {
        checked_threads(threads);
        const SweepLevels parsed = parse_levels(levels);
        const Topology t = topology(connectivity, periodic.value_or(surface.grid().periodic));
        py::gil_scoped_release unlocked;
        return sweep(surface, parsed, t, threads);
      },
      py::arg("surface"), py::kw_only(), py::arg("levels") = "exact", py::arg("connectivity") = 4,
      py::arg("periodic") = py::none(), py::arg("threads") = 1,
      "The bearing area A_c(z)/A0 and spot count N(z) for many levels in one pass. levels: \"exact\" (every "
      "distinct height), \"paper\" (500 steps of h_max/500 down to the mean plane) or a count of uniform "
      "steps; "
      "connectivity 4 or 8; periodic: wrap spots across the edges (default: the surface's own periodicity).");

  py::class_<LoadAreaCurve>(
      m, "LoadAreaCurve",
      "A load-area curve, the one currency between methods: load = P/(E* A0) ascending, "
      "area_fraction = A/A0, separation [m] and spots where the method has them (NaN "
      "otherwise), the method's name and parameters, and the wall time [s]. Arrays are "
      "read-only views (no copy).")
      .def_readonly("method", &LoadAreaCurve::method)
      .def_readonly("parameters", &LoadAreaCurve::parameters)
      .def_property_readonly(
          "load",
          [](const py::object& self) { return view_of(self.cast<const LoadAreaCurve&>().load, self); },
          "P/(E* A0) [-], ascending")
      .def_property_readonly(
          "area_fraction",
          [](const py::object& self) {
            return view_of(self.cast<const LoadAreaCurve&>().area_fraction, self);
          },
          "A/A0 [-]")
      .def_property_readonly(
          "separation",
          [](const py::object& self) { return view_of(self.cast<const LoadAreaCurve&>().separation, self); },
          "separation z [m] of the flat from the mean plane (NaN where the method has none)")
      .def_property_readonly(
          "spots",
          [](const py::object& self) { return view_of(self.cast<const LoadAreaCurve&>().spots, self); },
          "contact spots (NaN where the method does not count them)")
      .def_readonly("seconds", &LoadAreaCurve::seconds, "wall time of the computation [s]")
      .def("__len__", [](const LoadAreaCurve& c) { return c.load.size(); })
      .def("__repr__", [](const LoadAreaCurve& c) {
        return "LoadAreaCurve(method='" + c.method + "', " + std::to_string(c.load.size()) + " points)";
      });
}

}  // namespace contactbench::python
