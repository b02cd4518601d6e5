#include "contactbench/app/methods/bem_settings.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "contactbench/app/scene_text.hpp"
#include "contactbench/app/scene_toml.hpp"
#include "contactbench/bem/solver_registry.hpp"

namespace contactbench {

namespace {

using Row = Setting<BemSettings>;

// "`\"a\"`, `\"b\"`": choices as the docs' table writes them.
std::string quoted(const std::vector<std::string>& choices) {
  std::string text;
  for (const std::string& c : choices)
    text += (text.empty() ? "`\"" : ", `\"") + c + "\"`";
  return text;
}

SettingTable<BemSettings> make_table() {
  const std::string max_points = std::to_string(kMaxPointsASide);
  SettingTable<BemSettings> table;
  table.push_back(bind(
      Row{.key = "refine",
          .kind = SettingKind::integer,
          .accepted = "0, or [points a side of the surface, " + max_points + "]",
          .default_value = std::int64_t{0},
          .doc = "points a side the BEM solves on (Fourier refinement); 0 = the surface as given",
          .flag = {},
          .distributed = true,
          .owner_reads = true},
      [](BemSettings & s) -> auto& { return s.refine; }));
  table.push_back(bind(
      Row{.key = "tolerance",
          .kind = SettingKind::number,
          .accepted = "a number in [1e-13, 0.01]",
          .default_value = kDefaultTolerance,
          .default_text = "1e-8 (1e-6 in single precision)",
          .doc =
              "relative change of the pressure that ends the iteration (outside that range the criterion "
              "means "
              "nothing: looser stops far from the solution, tighter is round-off); converged also needs the "
              "gap "
              "left on the contact set within 100 x the tolerance of the height range (docs/solvers.md); in "
              "single precision at least 1e-6",
          .flag = {"--tolerance"},
          .python = true,
          .distributed = true,
          .ok = in_range(kSmallestTolerance, kLargestTolerance)},
      [](BemSettings & s) -> auto& { return s.solver.tolerance; }));
  table.push_back(bind(
      Row{.key = "max_iterations",
          .kind = SettingKind::integer,
          .accepted = "an integer in [1, 2147483647]",
          .default_value = std::int64_t{20000},
          .doc = "iteration limit per load",
          .flag = {"--max-iterations"},
          .python = true,
          .distributed = true,
          .ok = in_range(1, std::numeric_limits<std::int32_t>::max())},
      [](BemSettings & s) -> auto& { return s.solver.max_iterations; }));
  // Scope method: the stage holds the boundary resolved against the surface (BemStage::periodic), so that
  // an unset periodic and its value spelled out share one solve.
  table.push_back(bind(
      Row{.key = "periodic",
          .kind = SettingKind::boolean,
          .scope = SettingScope::method,
          .default_text = "the surface's",
          .doc = "solve the periodic or the non-periodic problem",
          .flag = {"--non-periodic", false},
          .python = true,
          .distributed = true},
      [](BemSettings & s) -> auto& { return s.periodic; }));
  table.push_back(bind_choice(
      Row{.key = "boundary",
          .kind = SettingKind::choice,
          .accepted = "`\"as_is\"`, `\"mirrored\"` (`\"mirrored\"` only for the non-periodic problem, "
                      "without adhesion, residual_topography and extrapolate)",
          .default_text =
              "`\"mirrored\"` for the non-periodic problem where it is accepted, else `\"as_is\"` (the run's "
              "parameters say which, and why)",
          .doc =
              "the edges of a non-periodic problem: `\"as_is\"` the finite patch pressed into the half-space "
              "(its edges act like a punch's), `\"mirrored\"` the patch extended evenly to twice its points "
              "a "
              "side and solved periodically (4 times the points), every statistic taken on the original "
              "patch (docs/solvers.md \"Mirrored boundary\"; results/studies/edges)",
          .flag = {"--boundary"},
          .distributed = true,
          .choices = {"as_is", "mirrored"}},
      [](BemSettings & s) -> auto& { return s.mirrored; }));
  table.push_back(bind_choice(
      Row{.key = "precision",
          .kind = SettingKind::choice,
          .accepted = "`\"double\"`, `\"single\"`",
          .default_value = std::string("double"),
          .doc = "iterate in single precision (half the memory; `tolerance` then >= 1e-6, its default)",
          .flag = {"--float", std::string("single")},
          .python = true,
          .choices = {"double", "single"}},
      [](BemSettings & s) -> auto& { return s.solver.single_precision; }));
  table.push_back(bind(
      Row{.key = "fields",
          .kind = SettingKind::text,
          .accepted = "a relative path prefix inside the run's output folder (`bem --fields`: any path)",
          .default_text = "none",
          .doc =
              "write the pressure [Pa], gap [m] and contact set (with adhesion also the attraction [Pa]) of "
              "the k-th load to `<prefix>_load<k>_<quantity>.txt`, each with its PNG and SVG map",
          .flag = {"--fields"},
          .distributed = true,
          .owner_reads = true},
      [](BemSettings & s) -> auto& { return s.fields; }));
  table.push_back(bind(
      Row{.key = "residual_topography",
          .kind = SettingKind::text,
          .accepted = "a file path (relative: to the scene file's folder); needs interface.hardness and "
                      "loads.path = \"as listed\"",
          .default_text = "none",
          .doc =
              "write the surface as the load path left it (heights lowered where it flowed plastically) to "
              "this file, in the project's text format (`stats` and `run` read it)",
          .owner_reads = true},
      [](BemSettings & s) -> auto& { return s.residual_topography; }));
  table.push_back(bind(
      Row{.key = "connectivity",
          .kind = SettingKind::integer,
          .scope = SettingScope::method,
          .accepted = "4, 8",
          .default_value = std::int64_t{4},
          .doc = "neighbours that join contact points into one spot",
          .flag = {"--connectivity"},
          .python = true,
          .ok =
              [](const SettingValue& v) {
                return std::get<std::int64_t>(v) == 4 || std::get<std::int64_t>(v) == 8;
              }},
      [](BemSettings & s) -> auto& { return s.connectivity; }));
  table.push_back(bind_choice(
      Row{.key = "solver",
          .kind = SettingKind::choice,
          .accepted = quoted(solver_names()),  // the registry's: a new solver is accepted here at once
          .default_value = std::string(solver_name(kDefaultSolver)),
          .doc = "the BEM iteration (docs/solvers.md): Polonsky & Keer's, the same Fourier-preconditioned, "
                 "or the "
                 "active-set method; the distributed solver has all three",
          .flag = {"--solver"},
          .python = true,
          .distributed_choices = {"polonsky_keer", "preconditioned_cg", "active_set"},
          .choices = solver_names()},
      [](BemSettings & s) -> auto& { return s.solver.solver; }));
  table.push_back(bind_choice(
      Row{.key = "adhesive_solver",
          .kind = SettingKind::choice,
          .accepted = "`\"fixed_point\"`, `\"constrained_cg\"` (the Dugdale law only), `\"projected_lbfgs\"` "
                      "(the exponential law, periodic problem only)",
          .default_value = std::string("fixed_point"),
          .doc =
              "with interface.adhesion (unused without it): the fixed point on the attraction around the "
              "contact solver, or first a constrained CG on the whole Dugdale problem whose state the fixed "
              "point then checks and settles, or the exponential law's total energy minimised over the gap "
              "by a projected L-BFGS (docs/solvers.md \"Adhesion\", docs/theory.md 10.11; results/bench/"
              "bem_adhesion_solvers.md); each is refused by name for a law or grid it cannot solve",
          .flag = {"--adhesive-solver"},
          .python = true,
          .choices = {"fixed_point", "constrained_cg", "projected_lbfgs"}},
      [](BemSettings & s) -> auto& { return s.adhesive_method; }));
  table.push_back(bind_choice(
      Row{.key = "load_path",
          .kind = SettingKind::choice,
          .accepted = "`\"scaled\"`, `\"extrapolated\"`, `\"cold\"`, `\"solver\"`",
          .default_value = std::string("solver"),
          .doc =
              "where each load after the first starts (loads are solved in increasing order): the previous "
              "solution scaled to the new load, the linear extrapolation of the last two in the load "
              "(clipped at 0, then scaled), cold (as a load alone), or the start the solver declares by "
              "measurement (docs/solvers.md \"Starts\")",
          .distributed_choices = {"scaled", "cold", "solver"},
          .choices = {"scaled", "extrapolated", "cold", "solver"}},
      [](BemSettings & s) -> auto& { return s.solver.load_path; }));
  table.push_back(bind(
      Row{.key = "extrapolate",
          .kind = SettingKind::boolean,
          .default_value = false,
          .doc =
              "solve every load again on twice the points a side (Fourier-refined; periodic surfaces only, "
              "refused before any stage otherwise) and compare by the Richardson-extrapolated area "
              "`area_fraction_extrapolated` of the node counts N (2 N(2n) - N(n), or at the observed order "
              "with `error_estimate = \"gci3\"`), with the error bar `area_fraction_error` that "
              "`error_estimate` chooses "
              "(docs/theory.md section 9); the table shows it as the reference's own uncertainty. Costs "
              "about "
              "5 times the single solve, and the third grid's",
          .distributed = true},
      [](BemSettings & s) -> auto& { return s.extrapolate; }));
  table.push_back(bind_choice(
      Row{.key = "error_estimate",
          .kind = SettingKind::choice,
          .accepted = "`\"gci3\"`, `\"gci2\"`, `\"calibrated3\"`",
          .default_value = std::string("gci3"),
          .doc =
              "with `extrapolate = true` (unused without it), the error bar `area_fraction_error` of the "
              "reference's area "
              "(docs/solvers.md \"Error bar of the reference\"): `\"gci3\"` Roache's grid convergence index "
              "from three grids, the observed order (at most 1) and the factor 1.25, or 3 when the order is "
              "more than 10 % off 1 (a third solve: on half the points a "
              "side when the surface is given on at most that many, +1/4 of the single solve; else on twice "
              "the finer grid's, +16 times); `\"gci2\"` from the two grids at order 1 with the factor 3 (no "
              "third solve); `\"calibrated3\"` the same three grids, the area extrapolated at order 1 and a "
              "bar calibrated per load band on the BEM's grid sequences (docs/theory.md section 9.2), 2.9 to "
              "6.5 times narrower than `\"gci3\"`; out of sample it covered 96 to 97 % of each load band "
              "(`\"gci3\"` 100 %), hence not the default. Calibrated by scripts/studies/error_bar.py",
          .distributed = true,
          .choices = {"gci2", "gci3", "calibrated3"}},
      [](BemSettings & s) -> auto& { return s.error_estimate; }));
  table.push_back(bind_choice(
      Row{.key = "area",
          .kind = SettingKind::choice,
          .scope = SettingScope::method,
          .accepted = "`\"corrected\"`, `\"nodes\"`",
          .default_value = std::string("corrected"),
          .doc =
              "the area the comparison uses: perimeter-corrected, or the plain node count (what a node-based "
              "finite-element model at that resolution reports; the paper's comparison as made, "
              "results/studies/paper_faithful). Not with `extrapolate = true`",
          .choices = {"corrected", "nodes"}},
      [](BemSettings & s) -> auto& { return s.node_area; }));
  table.push_back(bind(
      Row{.key = "allow_unconverged",
          .kind = SettingKind::boolean,
          .scope = SettingScope::method,
          .default_value = false,
          .doc = "a load that did not converge (its `converged` column 0, marked \"not converged\" in "
                 "table.md and "
                 "listed in summary.json's `unconverged_loads`) makes the run exit with status 3 after "
                 "writing its "
                 "results; true accepts it (exit 0, still marked), e.g. to time a fixed number of iterations",
          .flag = {"--allow-unconverged", true}},
      [](BemSettings & s) -> auto& { return s.allow_unconverged; }));
  return table;
}

}  // namespace

const SettingTable<BemSettings>& bem_settings() {
  static const SettingTable<BemSettings> table = make_table();
  return table;
}

void finish_bem_settings(
    BemSettings& settings, const std::vector<std::string>& given,
    const std::function<void(const std::string&, const std::string&, const std::string&)>& problem) {
  const auto was_given = [&](const char* key) {
    return std::find(given.begin(), given.end(), key) != given.end();
  };
  if (settings.solver.single_precision) {
    // Single precision resolves a relative change of about 1e-7: its default is the least it accepts.
    if (!was_given("tolerance"))
      settings.solver.tolerance = kSinglePrecisionTolerance;
    else if (settings.solver.tolerance < kSinglePrecisionTolerance)
      problem("tolerance", "out of range: got " + exact_number(settings.solver.tolerance),
              "a number in [1e-06, 0.01] (single precision cannot resolve less)");
  }
  if (settings.mirrored.value_or(false) && settings.extrapolate)
    problem("boundary",
            "boundary = \"mirrored\" and extrapolate = true: the extrapolation's finer grids "
            "are Fourier-refined from a periodic surface, not mirrored",
            "boundary = \"as_is\", or extrapolate = false");
  if (settings.node_area && settings.extrapolate)
    problem("area", "area = \"nodes\" and extrapolate = true ask for two different compared areas",
            "area = \"corrected\" (the default) with extrapolate = true, or extrapolate = false");
}

ResolvedBoundary resolve_boundary(const BemSettings& settings, bool periodic, bool adhesion) {
  if (settings.mirrored) return {.mirrored = *settings.mirrored, .as_is_because = {}};
  if (periodic) return {};  // no edges: nothing to choose
  const auto as_is = [](std::string why) {
    return ResolvedBoundary{.mirrored = false,
                            .as_is_because = "boundary unset, and \"mirrored\" is not available " + why};
  };
  if (adhesion) return as_is("with adhesion");
  if (!settings.residual_topography.empty()) return as_is("with residual_topography");
  if (settings.extrapolate) return as_is("with extrapolate = true");
  return {.mirrored = true, .as_is_because = {}};
}

}  // namespace contactbench
