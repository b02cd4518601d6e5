// Scenes (app/scene.hpp, app/scene_run.hpp, app/comparison.hpp, app/report_writers.hpp): read, run, compare
// and write the same files as `contactbench run` (app/run_command.cpp), with the report as Python objects.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <iostream>
#include <optional>

#include "bindings.hpp"
#include "contactbench/app/comparison.hpp"
#include "contactbench/app/load_area_plots.hpp"
#include "contactbench/app/output_folder.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/report_writers.hpp"
#include "contactbench/app/run_observer.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_run.hpp"

namespace contactbench::python {

namespace {

// A method's curve and result as Python sees them: copies (a few numbers per load) that also hold the scene's
// loads, so that a MethodCurve has `load` like every LoadAreaCurve; the C++ report holds the loads once.
struct ReportCurve {
  MethodCurve curve;
  std::vector<Real> load;
};

struct ReportMethod {
  MethodResult result;
  std::vector<Real> load;
  ReportCurve curve() const { return {result.curve, load}; }
};

SceneReport run(const Scene& scene, int threads, bool progress) {
  checked_threads(threads);
  const RunObserver observer = terminal_observer("contactbench (python)", progress);
  py::gil_scoped_release unlocked;
  return run_scene(scene, {.threads = threads, .observer = progress ? &observer : nullptr});
}

// write_report and the plots into `folder`, atomically, as `contactbench run` does; `command` is the
// provenance's record of what made the files.
void write(const std::filesystem::path& folder, const SceneReport& report, const Comparison& comparison,
           bool plots, const std::string& command) {
  const Provenance provenance = current_provenance(report.threads, command);
  py::gil_scoped_release unlocked;
  write_folder_atomically(folder, [&](const std::filesystem::path& staging) {
    write_report(staging, report, comparison, provenance);
    if (plots) draw_load_area_plots(staging, report, std::cerr);
  });
}

}  // namespace

void register_scene(py::module_& m) {
  py::class_<Scene>(m, "Scene", "A scene file as understood and validated (scenes/README.md).")
      .def_readonly("name", &Scene::name)
      .def_readonly("description", &Scene::description)
      .def_property_readonly("file", [](const Scene& s) { return s.file.string(); })
      .def_readonly("loads", &Scene::loads, "P/(E* A0), ascending (a list)")
      .def_property_readonly(
          "modulus", [](const Scene& s) { return s.material.estar; }, "E* [Pa]")
      .def_readonly("reference", &Scene::reference, "label of the reference method ('' for none)")
      .def_property_readonly(
          "methods",
          [](const Scene& s) {
            std::vector<std::string> labels;
            for (const MethodSpec& method : s.methods)
              labels.push_back(method.label);
            return labels;
          },
          "method labels, in the file's order")
      .def("to_toml", &to_toml, "the scene with defaults filled in, as TOML that read_scene accepts again")
      .def("to_json", &to_json, "the same as one JSON object");

  py::class_<ReportCurve>(
      m, "MethodCurve",
      "A method's curve at the scene's loads: load, area_fraction, separation, spots like a "
      "LoadAreaCurve, and the method's own columns. Arrays are read-only views.")
      .def_property_readonly(
          "load", [](const py::object& self) { return view_of(self.cast<const ReportCurve&>().load, self); },
          "P/(E* A0) [-], ascending: the scene's loads (SceneReport.loads)")
      .def_property_readonly(
          "area_fraction",
          [](const py::object& self) {
            return view_of(self.cast<const ReportCurve&>().curve.area_fraction, self);
          },
          "A/A0 as compared (MethodResult.compared_area says which area)")
      .def_property_readonly(
          "separation",
          [](const py::object& self) {
            return view_of(self.cast<const ReportCurve&>().curve.separation, self);
          },
          "[m] from the mean plane of the heights; NaN where the method has none")
      .def_property_readonly(
          "spots",
          [](const py::object& self) { return view_of(self.cast<const ReportCurve&>().curve.spots, self); },
          "contact spots; NaN where the method counts none")
      .def_property_readonly(
          "parameters", [](const ReportCurve& c) { return c.curve.parameters; }, "the method as run")
      .def_property_readonly(
          "columns",
          [](const py::object& self) {
            py::dict columns;
            for (const auto& [name, values] : self.cast<const ReportCurve&>().curve.columns)
              columns[py::str(name)] = view_of(values, self);
            return columns;
          },
          "the method's own columns (e.g. iterations, area_fraction_nodes for the BEM): name -> array")
      .def("__len__", [](const ReportCurve& c) { return c.load.size(); });

  py::class_<ReportMethod>(m, "MethodResult", "One method's result in a scene report.")
      .def_property_readonly(
          "label", [](const ReportMethod& r) { return r.result.label; }, "the method's label in the scene")
      .def_property_readonly(
          "method", [](const ReportMethod& r) { return r.result.method; },
          "the registry name: bem, plateau, gw_mccool, ...")
      .def_property_readonly(
          "compared_area", [](const ReportMethod& r) { return r.result.compared_area; },
          "which area curve.area_fraction is")
      .def_property_readonly("curve", &ReportMethod::curve, "MethodCurve at the scene's loads")
      .def_property_readonly(
          "columns", [](const py::object& self) { return py::dict(self.attr("curve").attr("columns")); },
          "the method's own columns (e.g. iterations, area_fraction_nodes for the BEM): name -> array")
      .def_property_readonly(
          "seconds", [](const ReportMethod& r) { return r.result.seconds; },
          "wall time of the stages the method needed [s]");

  py::class_<SceneReport>(m, "SceneReport", "What running a scene produced (app/scene_run.hpp).")
      .def_readonly("scene", &SceneReport::scene)
      .def_property_readonly(
          "loads", [](const SceneReport& r) { return r.loads(); }, "P/(E* A0) of every curve, held once")
      .def_readonly("grid", &SceneReport::grid, "the scene surface's grid (before a method's refinement)")
      .def_readonly("moments", &SceneReport::moments, "the scene surface's profile moments")
      .def_property_readonly(
          "stages",
          [](const SceneReport& r) {
            py::list stages;
            for (const StageRecord& s : r.stages)
              stages.append(py::make_tuple(s.name, s.seconds));
            return stages;
          },
          "every stage that ran, in order: a list of (name, seconds [s])")
      .def_property_readonly(
          "methods",
          [](const SceneReport& r) {
            std::vector<ReportMethod> methods;
            for (const MethodResult& method : r.methods)
              methods.push_back({method, r.loads()});
            return methods;
          },
          "MethodResult per method, in the scene's order")
      .def_property_readonly(
          "curves",
          [](const SceneReport& r) {
            py::dict curves;
            for (const MethodResult& method : r.methods)
              curves[py::str(method.label)] = ReportMethod{method, r.loads()}.curve();
            return curves;
          },
          "label -> MethodCurve")
      .def_readonly("threads", &SceneReport::threads)
      .def_readonly("seconds", &SceneReport::seconds, "the whole run [s]");

  py::class_<MethodComparison>(m, "MethodComparison", "One method judged against the scene's reference.")
      .def_readonly("label", &MethodComparison::label)
      .def_property_readonly(
          "relative_error",
          [](const py::object& self) {
            return view_of(self.cast<const MethodComparison&>().relative_error, self);
          },
          "A/A0 / (reference A/A0) - 1 at each load (NaN where either has no answer)")
      .def_readonly("max_abs_relative_error", &MethodComparison::max_abs_relative_error)
      .def_readonly("rms_relative_error", &MethodComparison::rms_relative_error)
      .def_readonly("kappa", &MethodComparison::kappa,
                    "areal kappa = (A/A0)/(p/(E* gbar)) at the smallest load")
      .def_readonly("kappa_nodes", &MethodComparison::kappa_nodes,
                    "the BEM's kappa by node count, else None");

  py::class_<Comparison>(m, "Comparison",
                         "Every method's curve judged against the reference (app/comparison.hpp).")
      .def_readonly("reference", &Comparison::reference)
      .def_readonly("rms_gradient", &Comparison::rms_gradient, "gbar of the scene's surface [-]")
      .def_readonly("kappa_load", &Comparison::kappa_load,
                    "the smallest load P/(E* A0), where kappa is taken")
      .def_readonly("methods", &Comparison::methods, "MethodComparison per method, in the report's order");

  m.def("read_scene", &read_scene, py::arg("path"),
        "Reads and validates a scene file (TOML); every problem is listed in one contactbench.SceneError.");
  m.def(
      "run_scene", &run, py::arg("scene"), py::kw_only(), py::arg("threads") = 1, py::arg("progress") = false,
      "Runs every method of the scene once (shared stages once): a SceneReport. progress: long stages report "
      "on stderr. Releases the GIL; not interruptible mid-run.");
  m.def("compare", &compare, py::arg("report"), "Every method against the reference: a Comparison.");
  m.def(
      "write_report",
      [](const std::filesystem::path& folder, const SceneReport& report, const Comparison& comparison,
         bool plots) {
        write(folder, report, comparison, plots,
              "python: contactbench.write_report(" + folder.string() + ")");
      },
      py::arg("folder"), py::arg("report"), py::arg("comparison"), py::kw_only(), py::arg("plots") = true,
      "Writes curves.csv, summary.json, table.md (and load_area.png/.svg with gnuplot when plots) into "
      "folder, "
      "atomically, as `contactbench run --out folder` does.");
  m.def(
      "run",
      [](const std::filesystem::path& scene_file, std::optional<std::filesystem::path> out, int threads,
         bool plots, bool progress) {
        const Scene scene = read_scene(scene_file);  // everything validated before any work
        if (out) check_replaceable_folder(*out);
        SceneReport report = run(scene, threads, progress);
        Comparison comparison = compare(report);
        if (out)
          write(*out, report, comparison, plots,
                "python: contactbench.run(" + scene_file.string() + ", out=" + out->string() +
                    ", threads=" + std::to_string(threads) + ")");
        return py::make_tuple(std::move(report), std::move(comparison));
      },
      py::arg("scene_file"), py::kw_only(), py::arg("out") = py::none(), py::arg("threads") = 1,
      py::arg("plots") = true, py::arg("progress") = false,
      "`contactbench run` from Python: read_scene, run_scene, compare, and with out= write_report into that "
      "folder (the CLI's files). Returns (SceneReport, Comparison).");
}

}  // namespace contactbench::python
