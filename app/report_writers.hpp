// The files a scene's run leaves (issue: curves.csv, summary.json, table.md), each made from the report and
// its comparison alone, and each written to a temporary name and renamed when complete.
#pragma once

#include <filesystem>
#include <ostream>

#include "contactbench/app/comparison.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/core/sweep.hpp"

namespace contactbench {

// One row per method and load: method, separation, load, area_fraction, spots, then every method's own
// columns (empty where a method has none). Comment lines (#) first: what made it.
void write_curves_csv(std::ostream& out, const SceneReport& report, const Provenance& provenance);

// The scene as understood (defaults filled in), provenance, the stages that ran and their cost, and per
// method its wall time, its errors against the reference and its areal kappa.
void write_summary_json(std::ostream& out, const SceneReport& report, const Comparison& comparison,
                        const Provenance& provenance);

// The comparison a person would paste into a paper: per method its time, kappa and errors; then A/A0 of
// every method at every load.
void write_table_md(std::ostream& out, const SceneReport& report, const Comparison& comparison,
                    const Provenance& provenance);

// A sweep level by level (a plateau method's MethodCurve::levels): z, area_fraction_nodes, spots, after one
// comment line that starts with `origin` (e.g. "contactbench sweep of s.txt") and says what the rows are.
void write_levels_csv(std::ostream& out, const SweepCurve& levels, const std::string& origin);
// A method's columns along the scene's load path (MethodCurve::path_columns), one row per step.
void write_path_csv(std::ostream& out, const std::vector<std::pair<std::string, std::vector<Real>>>& columns,
                    const std::string& origin);

// All of the above into `folder` (created if needed): curves.csv, summary.json, table.md, and
// <label>_levels.csv of every method with a level curve.
void write_report(const std::filesystem::path& folder, const SceneReport& report,
                  const Comparison& comparison, const Provenance& provenance);

}  // namespace contactbench
