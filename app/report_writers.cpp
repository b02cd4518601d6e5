#include "contactbench/app/report_writers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contactbench/app/adhesive_path_csv.hpp"
#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/unconverged.hpp"
#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/topology.hpp"

namespace contactbench {

namespace {

// Every method's own column names, in order of first appearance.
std::vector<std::string> extra_columns(const SceneReport& report) {
  std::vector<std::string> names;
  for (const MethodResult& m : report.methods)
    for (const auto& column : m.curve.columns)
      if (std::find(names.begin(), names.end(), column.first) == names.end()) names.push_back(column.first);
  return names;
}

std::string csv_number(Real value) {
  return std::isfinite(value) ? json_number(value) : "";
}

// A number for a Markdown table: 4 significant digits, "n/a" where a method has no answer.
std::string table_number(Real value, const char* format = "%.4g") {
  if (!std::isfinite(value)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// A relative error in per cent: signed for one load, unsigned for a magnitude (max, rms).
std::string percent(Real value, bool is_signed = true) {
  if (!std::isfinite(value)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, is_signed ? "%+.1f %%" : "%.1f %%", 100 * value);
  return text;
}

std::string stamp(const Provenance& p) {
  return "commit " + p.commit + ", " + p.date + ", " + threads_text(p) + ", " + p.machine;
}

// The approach-retract path's summary (its states are in <label>_approach_retract.csv): loads as P/(E* A0).
JsonObject path_json(const AdhesivePath& path, const SceneReport& report) {
  const Real estar = report.scene.material.estar;
  JsonObject o;
  o.add("file_suffix", "_approach_retract.csv");
  o.add("pull_off_load", path.pull_off_pressure / estar).add("pull_off_separation", path.pull_off_separation);
  o.add("pull_off_located", path.pull_off_located);
  o.add("cycle_work", path.cycle_work).add("released_energy", path.released_energy);
  std::vector<JsonObject> jumps;
  for (const AdhesiveJump& jump : path.jumps) {
    JsonObject j;
    j.add("into_contact", jump.into_contact)
        .add("separation_before", jump.separation_before)
        .add("separation_after", jump.separation_after)
        .add("load_before", jump.mean_pressure_before / estar)
        .add("load_after", jump.mean_pressure_after / estar)
        .add("released_energy", jump.released_energy);
    jumps.push_back(std::move(j));
  }
  o.add("jumps", std::move(jumps));
  o.add("states", static_cast<long long>(path.states.size())).add("converged", path.converged);
  return o;
}

JsonObject provenance_json(const Provenance& p) {
  JsonObject o;
  o.add("commit", p.commit).add("date", p.date).add("threads", p.threads);
  if (p.ranks > 1) o.add("ranks", static_cast<long long>(p.ranks));  // threads is then each rank's
  o.add("machine", p.machine);
  o.add("command", p.command);
  return o;
}

// "(± x % at most)": the largest of the reference's own relative discretisation errors, when it has them.
std::string reference_uncertainty_text(const Comparison& comparison) {
  Real largest = 0;
  for (const Real u : comparison.reference_uncertainty)
    if (std::isfinite(u)) largest = std::max(largest, u);
  return comparison.reference_uncertainty.empty()
             ? std::string()
             : " (its own error up to ± " + percent(largest, false) + ")";
}

const char* quantity_title(Quantity quantity) {
  return quantity == Quantity::mean_gap ? "Mean gap u-bar [m]"
                                        : "Contact stiffness per unit area K = -dP/dd [Pa/m]";
}

// For a compared quantity other than the area (Scene::compare[index]): each method's errors, then its
// values load by load; "n/a" for a method that gives none.
void write_quantity_tables(std::ostream& out, const SceneReport& report, const Comparison& comparison,
                           std::size_t index) {
  const Quantity quantity = report.scene.compare[index];
  const std::size_t slot = index - 1;  // MethodComparison::quantities leaves out the area, always first
  out << "\n"
      << quantity_title(quantity) << " (docs/theory.md section 12)"
      << (comparison.reference.empty() ? "" : ", relative to " + comparison.reference) << ":\n\n";
  out << "| method | max abs error | rms error |\n|---|---:|---:|\n";
  for (std::size_t m = 0; m < report.methods.size(); ++m) {
    const MethodResult& r = report.methods[m];
    const QuantityComparison& q = comparison.methods[m].quantities[slot];
    out << "| " << r.label << r.note_suffix() << " | ";
    if (!q.given)
      out << "n/a (the method gives none) | |\n";
    else if (r.label == comparison.reference)
      out << "reference | |\n";
    else
      out << percent(q.max_abs_relative_error, false) << " | " << percent(q.rms_relative_error, false)
          << " |\n";
  }
  out << "\n| P/(E* A0) |";
  for (const MethodResult& r : report.methods)
    out << ' ' << r.label << " |";
  out << "\n|---:|";
  for (std::size_t m = 0; m < report.methods.size(); ++m)
    out << "---:|";
  out << '\n';
  for (std::size_t k = 0; k < report.loads().size(); ++k) {
    out << "| " << table_number(report.loads()[k], "%.3g") << " |";
    for (std::size_t m = 0; m < report.methods.size(); ++m) {
      const MethodResult& r = report.methods[m];
      const QuantityComparison& q = comparison.methods[m].quantities[slot];
      const std::vector<Real>& values = r.curve.values(quantity);
      out << ' ' << (values.empty() ? std::string("n/a") : table_number(values[k]));
      if (!q.relative_error.empty() && r.label != comparison.reference)
        out << " (" << percent(q.relative_error[k]) << ")";
      out << " |";
    }
    out << '\n';
  }
}

}  // namespace

void write_curves_csv(std::ostream& out, const SceneReport& report, const Provenance& provenance) {
  const std::vector<std::string> extras = extra_columns(report);
  out << "# contactbench run of scene " << report.scene.name << " (" << stamp(provenance)
      << "): " << provenance.command
      << "\n# load = P/(E* A0); separation [m] of the flat from the mean plane of the heights; area_fraction "
         "= A/A0 "
         "as compared (the BEM's is area_fraction_corrected, or area_fraction_extrapolated with extrapolate "
         "= true; the plateau model's area_fraction_nodes); empty "
         "cells: the method has no such value\n";
  // What each method ran (for the BEM: its solver, boundary and tolerance), one comment line each.
  for (const MethodResult& m : report.methods)
    out << "# " << m.label << ": " << m.curve.parameters << '\n';
  // The compared quantities beyond the area (Scene::compare), only when the scene names them: a scene of
  // areas writes exactly the columns it wrote before.
  std::vector<Quantity> others;
  for (const Quantity q : report.scene.compare)
    if (q != Quantity::area) others.push_back(q);
  if (!others.empty())
    out << "# mean_gap [m]: mean of the gap over the nominal area; stiffness [Pa/m]: K = -dP/dd per unit "
           "area, d the flat's rigid approach (docs/theory.md section 12); empty: the method gives none\n";
  out << "method,separation,load,area_fraction,spots";
  for (const Quantity q : others)
    out << ',' << quantity_name(q);
  for (const std::string& name : extras)
    out << ',' << name;
  out << '\n';
  const std::vector<Real>& loads = report.loads();
  for (const MethodResult& m : report.methods)
    for (std::size_t k = 0; k < loads.size(); ++k) {
      out << m.label << ',' << csv_number(m.curve.separation[k]) << ',' << csv_number(loads[k]) << ','
          << csv_number(m.curve.area_fraction[k]) << ',' << csv_number(m.curve.spots[k]);
      for (const Quantity q : others) {
        const std::vector<Real>& values = m.curve.values(q);
        out << ',' << (values.empty() ? std::string() : csv_number(values[k]));
      }
      for (const std::string& name : extras) {
        out << ',';
        for (const auto& [column, values] : m.curve.columns)
          if (column == name) out << csv_number(values[k]);
      }
      out << '\n';
    }
}

void write_summary_json(std::ostream& out, const SceneReport& report, const Comparison& comparison,
                        const Provenance& provenance) {
  JsonObject root;
  root.add("scene", report.scene.name);
  root.add_raw("scene_as_understood", to_json(report.scene));
  root.add("provenance", provenance_json(provenance));
  JsonObject surface;
  surface.add("nx", static_cast<long long>(report.grid.nx)).add("ny", static_cast<long long>(report.grid.ny));
  surface.add("lx", report.grid.lx).add("ly", report.grid.ly).add("periodic", report.grid.periodic);
  surface.add("m0", report.moments.m0).add("m2x", report.moments.m2x).add("m2y", report.moments.m2y);
  surface.add("m4x", report.moments.m4x).add("m4y", report.moments.m4y);
  surface.add("rms_gradient", comparison.rms_gradient);
  if (!report.line_scan.empty()) surface.add("line_scan", report.line_scan);
  root.add("surface", std::move(surface));
  if (report.ranks > 1) {  // run as several MPI ranks (docs/mpi.md)
    JsonObject distributed;
    distributed.add("ranks", static_cast<long long>(report.ranks));
    distributed.add("bem_bytes_per_rank", static_cast<long long>(report.bytes_per_rank));
    // The scene's whole heights on rank 0: 0 when a generated surface stayed on the slabs (docs/mpi.md).
    distributed.add("rank0_surface_bytes", static_cast<long long>(report.root_surface_bytes));
    root.add("distributed", std::move(distributed));
  }
  std::vector<JsonObject> stages;
  for (const StageRecord& s : report.stages) {
    JsonObject o;
    o.add("name", s.name).add("seconds", s.seconds);
    stages.push_back(std::move(o));
  }
  root.add("stages", std::move(stages));
  root.add("reference", comparison.reference);
  root.add("kappa_load", comparison.kappa_load);
  root.add("loads", std::span<const double>(report.loads()));
  if (!comparison.reference_uncertainty.empty())
    root.add("reference_relative_uncertainty", std::span<const double>(comparison.reference_uncertainty));
  std::vector<JsonObject> methods;
  for (std::size_t m = 0; m < report.methods.size(); ++m) {
    const MethodResult& r = report.methods[m];
    const MethodComparison& c = comparison.methods[m];
    JsonObject o;
    o.add("label", r.label).add("method", r.method).add("parameters", r.curve.parameters);
    o.add("compared_area", r.compared_area);
    if (!r.note.empty()) o.add("note", r.note);
    if (!r.ignored_effects.empty()) o.add("ignored_effects", std::span<const std::string>(r.ignored_effects));
    o.add("seconds", r.seconds).add("kappa", c.kappa);
    if (c.kappa_nodes) o.add("kappa_nodes", *c.kappa_nodes);
    o.add("area_fraction", std::span<const double>(r.curve.area_fraction));
    o.add("relative_error", std::span<const double>(c.relative_error));
    o.add("max_abs_relative_error", c.max_abs_relative_error).add("rms_relative_error", c.rms_relative_error);
    // Each further compared quantity: its values, or "n/a" when the method gives none, and its errors.
    for (const QuantityComparison& q : c.quantities) {
      const std::string name(quantity_name(q.quantity));
      if (!q.given) {
        o.add(name, std::string_view("n/a"));
        continue;
      }
      o.add(name, std::span<const double>(r.curve.values(q.quantity)));
      if (!q.relative_error.empty()) {
        o.add(name + "_relative_error", std::span<const double>(q.relative_error));
        o.add(name + "_max_abs_relative_error", q.max_abs_relative_error);
        o.add(name + "_rms_relative_error", q.rms_relative_error);
      }
    }
    // The columns the method repeats here (the BEM's extrapolated area), and its own error estimate.
    for (const std::string& name : r.curve.summary_columns)
      for (const auto& [column, values] : r.curve.columns)
        if (column == name) o.add(name, std::span<const double>(values));
    if (!r.curve.area_fraction_error.empty())
      o.add("area_fraction_error", std::span<const double>(r.curve.area_fraction_error));
    // Where the method's iteration did not converge (app/unconverged.hpp): those loads' answers, and every
    // error against them when the method is the reference, are not to be trusted.
    std::vector<double> unconverged;
    for (const std::size_t k : unconverged_loads(r.curve))
      unconverged.push_back(report.loads()[k]);
    o.add("unconverged_loads", std::span<const double>(unconverged));
    if (r.curve.approach_retract) o.add("approach_retract", path_json(*r.curve.approach_retract, report));
    methods.push_back(std::move(o));
  }
  root.add("methods", std::move(methods));
  root.add("converged", describe_unconverged(report).empty());
  root.add("seconds", report.seconds);
  out << root.str() << '\n';
}

void write_table_md(std::ostream& out, const SceneReport& report, const Comparison& comparison,
                    const Provenance& provenance) {
  out << "# " << report.scene.name << ": real contact area against load\n\n";
  if (!report.scene.description.empty()) out << report.scene.description << "\n\n";
  if (!report.line_scan.empty())
    out << report.line_scan;
  else
    out << "Surface " << report.grid.nx << " x " << report.grid.ny << " points, "
        << table_number(report.grid.lx * 1e6) << " x " << table_number(report.grid.ly * 1e6) << " um, "
        << (report.grid.periodic ? "periodic" : "non-periodic");
  out << "; E* = " << table_number(report.scene.material.estar)
      << " Pa; areal rms gradient gbar = " << table_number(comparison.rms_gradient)
      << ". Loads are P/(E* A0); kappa is the areal kappa (A/A0)/(p/(E* gbar)) at the smallest load, "
      << table_number(comparison.kappa_load) << " (docs/theory.md section 0)."
      << (comparison.reference.empty()
              ? std::string(" No reference: no errors.")
              : " Errors are relative to " + comparison.reference + ", load by load.")
      << "\n\n";
  out << "| method | time [s] | kappa | max abs error | rms error |\n|---|---:|---:|---:|---:|\n";
  for (std::size_t m = 0; m < report.methods.size(); ++m) {
    const MethodResult& r = report.methods[m];
    const MethodComparison& c = comparison.methods[m];
    out << "| " << r.label << r.note_suffix() << " | " << table_number(r.seconds, "%.3g") << " | "
        << table_number(c.kappa, "%.3f");
    if (c.kappa_nodes) out << " (nodes " << table_number(*c.kappa_nodes, "%.3f") << ")";
    out << " | "
        << (r.label == comparison.reference ? "reference" + reference_uncertainty_text(comparison)
                                            : percent(c.max_abs_relative_error, false))
        << " | " << (r.label == comparison.reference ? "" : percent(c.rms_relative_error, false)) << " |\n";
  }
  if (const std::string unconverged = describe_unconverged(report); !unconverged.empty())
    out << "\n**Not converged**: " << unconverged
        << ". Those areas are marked below; where the reference did not converge, the errors against it "
           "at those loads are not to be trusted.\n";
  out << "\nA/A0 at each load" << (comparison.reference.empty() ? "" : " (relative error to the reference)")
      << ":\n\n| P/(E* A0) |";
  for (const MethodResult& r : report.methods)
    out << ' ' << r.label << " |";
  out << "\n|---:|";
  for (std::size_t m = 0; m < report.methods.size(); ++m)
    out << "---:|";
  out << '\n';
  std::vector<std::vector<std::size_t>> unconverged;  // per method
  for (const MethodResult& r : report.methods)
    unconverged.push_back(unconverged_loads(r.curve));
  for (std::size_t k = 0; k < report.loads().size(); ++k) {
    out << "| " << table_number(report.loads()[k], "%.3g") << " |";
    for (std::size_t m = 0; m < report.methods.size(); ++m) {
      const MethodResult& r = report.methods[m];
      out << ' ' << table_number(r.curve.area_fraction[k]);
      if (std::find(unconverged[m].begin(), unconverged[m].end(), k) != unconverged[m].end())
        out << " (not converged)";
      if (r.label == comparison.reference && !comparison.reference_uncertainty.empty())
        out << " (± " << percent(comparison.reference_uncertainty[k], false) << ")";
      if (!comparison.methods[m].relative_error.empty() && r.label != comparison.reference)
        out << " (" << percent(comparison.methods[m].relative_error[k]) << ")";
      out << " |";
    }
    out << '\n';
  }
  for (std::size_t index = 0; index < report.scene.compare.size(); ++index)
    if (report.scene.compare[index] != Quantity::area) write_quantity_tables(out, report, comparison, index);
  out << "\nMethods as run, and the area each is compared by:\n\n";
  for (const MethodResult& r : report.methods)
    out << "- " << r.label << ": " << r.curve.parameters << "; compared area: " << r.compared_area << '\n';
  for (const MethodResult& r : report.methods)
    if (r.curve.approach_retract) {
      const AdhesivePath& path = *r.curve.approach_retract;
      const Real estar = report.scene.material.estar;
      out << "\nApproach-retract path of " << r.label << " (" << r.label
          << "_approach_retract.csv and its plot): " << path.states.size()
          << " states, pull-off P/(E* A0) = " << table_number(path.pull_off_pressure / estar)
          << " at separation " << table_number(path.pull_off_separation) << " m ("
          << (path.pull_off_located ? "located between two samples" : "the least sample: not bracketed")
          << "), " << path.jumps.size() << " jumps (energy they release "
          << table_number(path.released_energy) << " J/m^2, work around the cycle "
          << table_number(path.cycle_work) << " J/m^2)"
          << (path.converged ? "" : "; NOT CONVERGED: some states did not converge") << ".\n";
    }
  out << "\nStages that ran:";
  for (const StageRecord& s : report.stages)
    out << ' ' << s.name << " " << table_number(s.seconds, "%.3g") << " s;";
  out << "\n\nMade by `" << provenance.command << "` (" << stamp(provenance) << ").\n";
}

void write_levels_csv(std::ostream& out, const SweepCurve& levels, const std::string& origin) {
  out << "# " << origin << ": " << describe(levels.topology)
      << "; row j: the set {h > z}, z from the mean plane [m]; area_fraction_nodes = nodes in the set / "
         "all\n";
  out << "z,area_fraction_nodes,spots\n";
  for (std::size_t j = 0; j < levels.z.size(); ++j)
    out << json_number(levels.z[j]) << ',' << json_number(levels.area_fraction[j]) << ',' << levels.spots[j]
        << '\n';
}

void write_path_csv(std::ostream& out, const std::vector<std::pair<std::string, std::vector<Real>>>& columns,
                    const std::string& origin) {
  out << "# " << origin
      << ": one row per step of the load path (loads.path = \"as listed\"); direction +1 loading, -1 "
         "unloading, 0 the same load again\n";
  for (std::size_t c = 0; c < columns.size(); ++c)
    out << (c ? "," : "") << columns[c].first;
  out << '\n';
  const std::size_t rows = columns.front().second.size();
  for (std::size_t k = 0; k < rows; ++k) {
    for (std::size_t c = 0; c < columns.size(); ++c)
      out << (c ? "," : "") << json_number(columns[c].second[k]);
    out << '\n';
  }
}

void write_report(const std::filesystem::path& folder, const SceneReport& report,
                  const Comparison& comparison, const Provenance& provenance) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw Error("cannot create the output folder " + folder.string() + ": " + error.message());
  write_file_atomically(folder / "curves.csv",
                        [&](std::ostream& out) { write_curves_csv(out, report, provenance); });
  write_file_atomically(folder / "summary.json",
                        [&](std::ostream& out) { write_summary_json(out, report, comparison, provenance); });
  write_file_atomically(folder / "table.md",
                        [&](std::ostream& out) { write_table_md(out, report, comparison, provenance); });
  for (const MethodResult& m : report.methods)
    if (m.curve.levels)
      write_file_atomically(folder / (m.label + "_levels.csv"), [&](std::ostream& out) {
        write_levels_csv(out, *m.curve.levels,
                         "contactbench run of scene " + report.scene.name + ", " + m.label);
      });
  for (const MethodResult& m : report.methods)
    if (!m.curve.path_columns.empty())
      write_file_atomically(folder / (m.label + "_path.csv"), [&](std::ostream& out) {
        write_path_csv(out, m.curve.path_columns,
                       "contactbench run of scene " + report.scene.name + ", " + m.label + " (" +
                           stamp(provenance) + ")");
      });
  for (const MethodResult& m : report.methods)
    if (m.curve.approach_retract)
      write_file_atomically(folder / (m.label + "_approach_retract.csv"), [&](std::ostream& out) {
        write_adhesive_path_csv(
            out, *m.curve.approach_retract, report.scene.material.estar, m.curve.approach_retract_points,
            "contactbench run of scene " + report.scene.name + ", " + m.label + ": approach-retract path",
            provenance);
      });
  for (const MethodResult& m : report.methods)
    if (m.curve.distributions) {
      const std::string origin = "contactbench run of scene " + report.scene.name + ", " + m.label + " (" +
                                 stamp(provenance) + "): " + provenance.command;
      const LoadDistributions& d = *m.curve.distributions;
      write_file_atomically(folder / (m.label + "_pressure_distribution.csv"),
                            [&](std::ostream& out) { write_pressure_distribution_csv(out, d, origin); });
      write_file_atomically(folder / (m.label + "_gap_distribution.csv"),
                            [&](std::ostream& out) { write_gap_distribution_csv(out, d, origin); });
      write_file_atomically(folder / (m.label + "_patch_sizes.csv"),
                            [&](std::ostream& out) { write_patch_sizes_csv(out, d, origin); });
    }
}

}  // namespace contactbench
