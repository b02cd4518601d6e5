// The boundary-element ground truth as a method of a scene: Polonsky-Keer (bem/bem_solver.hpp) at every
// scene load, its area perimeter-corrected (bem/contact_statistics.hpp; docs/theory.md section 6).
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include "contactbench/app/load_fields.hpp"
#include "contactbench/app/methods/bem_settings.hpp"
#include "contactbench/app/methods/method.hpp"
#include "contactbench/app/methods/refine_key.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/scene_text.hpp"
#include "contactbench/app/scene_toml.hpp"
#include "contactbench/app/section.hpp"
#include "contactbench/app/stage_runner.hpp"
#include "contactbench/app/stages.hpp"
#include "contactbench/bem/grid_convergence.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/memory_budget.hpp"
#include "contactbench/core/scales.hpp"
#include "contactbench/theories/persson.hpp"

namespace contactbench {

namespace {

// Loads above this many times (height range / pixel) are refused as full contact whose pressure variation
// double precision cannot resolve beside the mean (check_magnitudes): the variation is about E* (height range
// / pixel), the mean load x E*, so at this ratio it is still resolved to 1e6 x 2.2e-16 = 2e-10 of itself,
// inside the residual the default tolerance accepts (100 x 1e-8); far beyond it, it is lost.
constexpr Real kFullContactResolution = 1e6;

// The width of the attractive zone, in pixels at the contact edge, from which the adhesive BEM meets Maugis'
// sphere to 3 % (tests/test_adhesive_bem.cpp: 8-13 pixels at λ = 1, 128^2; the radius is 1.3 % off there).
constexpr Real kResolvedZonePixels = 5;

// With an attraction: per load the pull of the attraction (mean a / E*, in the loads' unit: the repulsive
// load is the load plus it), the attractive zone outside contact (its nodes / all), the zone's width in
// pixels at the contact edge (bem/adhesive_solver.hpp: below a few pixels the law is not resolved) and the
// outer iterations.
void add_adhesive_columns(const BemProducts& products, Real estar, MethodCurve& curve) {
  std::vector<Real> pull, zone, width, outer;
  for (const AdhesiveLoad& load : products.adhesive) {
    pull.push_back(load.adhesive_pressure / estar);
    zone.push_back(static_cast<Real>(load.attractive_points) / static_cast<Real>(products.points));
    width.push_back(load.zone_pixels);
    outer.push_back(static_cast<Real>(load.outer_iterations));
  }
  curve.columns.emplace_back("adhesive_load", pull);
  curve.columns.emplace_back("attractive_fraction", zone);
  curve.columns.emplace_back("zone_pixels", width);
  curve.columns.emplace_back("outer_iterations", outer);
  // Whether the law is resolved: the narrowest zone of the curve against the width where the adhesive BEM
  // meets Maugis' sphere to 3 % (tests/test_adhesive_bem.cpp).
  const auto narrowest = std::min_element(width.begin(), width.end());
  if (narrowest != width.end() && *narrowest < kResolvedZonePixels) {
    std::ostringstream text;
    text << "; the attractive zone at the contact edge is down to " << *narrowest
         << " pixels wide, below the " << kResolvedZonePixels
         << " that resolve the attraction's law (docs/solvers.md \"Adhesion\"): its range is not resolved "
            "on this grid, and the answer is the grid's as much as the law's";
    curve.parameters += text.str();
  }
}

// The solve answering each of the scene's loads (ascending): the k-th without a path; along one, the first
// step of the path at that load (the path lists every scene load: they are its values, sorted).
std::vector<std::size_t> solve_of_load(const std::vector<Real>& loads, const std::vector<Real>& path) {
  std::vector<std::size_t> index(loads.size());
  for (std::size_t k = 0; k < loads.size(); ++k)
    index[k] = path.empty()
                   ? k
                   : static_cast<std::size_t>(std::find(path.begin(), path.end(), loads[k]) - path.begin());
  return index;
}

class BemMethod final : public Method {
 public:
  std::string_view name() const override { return "bem"; }
  std::vector<Effect> models() const override { return {Effect::hardness, Effect::adhesion}; }
  bool is_ground_truth() const override { return true; }
  std::string compared_area() const override {
    if (settings_.node_area)
      return "area_fraction_nodes (contact nodes / all nodes, as a node-based finite-element model reports "
             "it; area = \"nodes\")";
    if (settings_.extrapolate && settings_.error_estimate == ErrorEstimate::calibrated3)
      return "area_fraction_extrapolated (the node counts on three grids, Richardson-extrapolated at order "
             "1; "
             "its error bar, calibrated on the BEM's grid sequences, is area_fraction_error; docs/theory.md "
             "section 9.2)";
    if (settings_.extrapolate && uses_third_grid(settings_.error_estimate))
      return "area_fraction_extrapolated (the node counts on three grids, Richardson-extrapolated at the "
             "observed "
             "order; its error bar, Roache's grid convergence index, is area_fraction_error; docs/theory.md "
             "section 9.2)";
    if (settings_.extrapolate)
      return "area_fraction_extrapolated (the node counts on the grid and on twice its points a side, "
             "Richardson-extrapolated at order 1; its error bar, the two-grid GCI, is area_fraction_error; "
             "docs/theory.md section 9.2)";
    return "area_fraction_corrected (contact nodes less the perimeter band of Yastrebov, Anciaux and "
           "Molinari 2017; the node count is area_fraction_nodes; on a periodic surface without hardness or "
           "adhesion its calibrated error bar is area_fraction_error, docs/theory.md section 9.2)";
  }

  // Its keys are declared once, in app/methods/bem_settings.cpp; read() adds what depends on the scene.
  void read(const Section& s, const SceneContext& context) override {
    std::vector<std::string_view> keys{"method", "hardness"};
    for (const Setting<BemSettings>& row : bem_settings())
      keys.push_back(row.key);
    s.reject_unknown(keys);
    settings_ = default_settings(bem_settings());
    const std::vector<std::string> given = read_settings(s, bem_settings(), settings_);
    settings_.refine = read_refine_key(s, context, settings_.refine);
    // Stored as written: `contactbench run` writes it inside the output folder (RunOptions::fields_folder),
    // `contactbench bem --fields` where the path says.
    if (const auto fields = s.string("fields", false, find_setting(bem_settings(), "fields")->accepted))
      settings_.fields = *fields;
    if (const auto residual = s.string("residual_topography", false,
                                       find_setting(bem_settings(), "residual_topography")->accepted))
      settings_.residual_topography = (context.folder / *residual).lexically_normal().string();
    if (s.has("hardness"))  // the key of earlier versions: an effect of the interface, not of one method
      s.problem("hardness",
                "the hardness is a property of the interface, for every method, not a key of the BEM",
                "interface.hardness = <H [Pa]> in the scene's [interface] table");
    finish_bem_settings(settings_, given,
                        [&](const std::string& key, const std::string& reason, const std::string& accepted) {
                          s.problem(key, reason, accepted);
                        });
  }

  void write(SceneKeys& keys) const override { write_settings(keys, bem_settings(), settings_); }

  MethodNeeds needs(const SceneContext& context) const override {
    BemStage stage;
    stage.settings = default_settings(bem_settings());
    copy_settings(bem_settings(), SettingScope::solve, settings_, stage.settings);
    stage.periodic = settings_.periodic.value_or(context.surface_periodic);
    // Resolved here, so that an unset boundary and its value spelled out share one solve.
    const ResolvedBoundary boundary =
        resolve_boundary(settings_, stage.periodic, context.interface.adhesion.has_value());
    stage.settings.mirrored = boundary.mirrored;
    stage.as_is_because = boundary.as_is_because;
    stage.hardness = context.interface.hardness;  // absent, or ignored: purely elastic
    stage.adhesion = context.interface.adhesion;  // absent, or ignored: non-adhesive
    stage.load_path = context.load_path;          // empty: the scene's loads, ascending
    return {
        .moments = false, .sweep = std::nullopt, .bem = stage, .bem_connectivity = settings_.connectivity};
  }

  void preflight(const MethodCheck& check) const override {
    const bool path = !check.scene.load_path.empty();
    const std::size_t solves = path ? check.scene.load_path.size() : check.scene.loads.size();
    if (!settings_.fields.empty() && !check.fields_folder.empty()) {
      // Inside the run's output folder, which the run makes new: a relative prefix that stays inside it.
      const std::filesystem::path prefix(settings_.fields);
      const bool inside =
          prefix.is_relative() && prefix.has_filename() &&
          std::none_of(prefix.begin(), prefix.end(), [](const auto& part) { return part == ".."; });
      if (!inside)
        check.problem("fields", "'" + settings_.fields + "' leaves the run's output folder",
                      "a relative prefix inside the output folder, such as \"fields\" or \"maps/surface\"");
    } else if (!settings_.fields.empty()) {
      // Field files are never written over a device, a link or a folder (app/output.hpp).
      try {
        check_output_prefix(settings_.fields, "fields");
        for (std::size_t k = 0; k < solves; ++k)
          for (const char* field : field_quantities(check.interface.adhesion.has_value()))
            check_replaceable_file(field_path(settings_.fields, k + 1, field));
      } catch (const Error& e) {
        check.problem("fields", e.what(), "a prefix of new or regular files in an existing folder");
      }
    }
    if (!settings_.residual_topography.empty()) {
      if (!check.interface.hardness || !path)
        check.problem("residual_topography",
                      "the surface changes only where it flows plastically along a load path, and this scene "
                      "has " +
                          std::string(!check.interface.hardness ? "no hardness" : "no load path"),
                      "interface.hardness and loads.path = \"as listed\", or no residual_topography");
      try {
        check_replaceable_file(settings_.residual_topography);
      } catch (const Error& e) {
        check.problem("residual_topography", e.what(), "a new or regular file in an existing folder");
      }
    }
    if (path && settings_.extrapolate)
      check.problem("extrapolate",
                    "the extrapolated area is not defined along a load path (the finer grid would flow "
                    "differently)",
                    "extrapolate = false, or loads.path = \"ascending\"");
    if (settings_.mirrored.value_or(false)) {  // declared: refused where unavailable (unset: falls back)
      // Mirroring a periodic surface would change it (its seams become reflections): refused, not a no-op,
      // so that a scene never reads as mirrored when it was not (docs/solvers.md "Mirrored boundary").
      if (settings_.periodic.value_or(check.surface.grid().periodic))
        check.problem("boundary",
                      "boundary = \"mirrored\" is for the non-periodic problem, and this one is periodic (" +
                          std::string(settings_.periodic ? "periodic = true" : "the surface is periodic") +
                          ")",
                      "boundary = \"as_is\", or periodic = false to treat the surface as a finite record");
      else if (check.interface.adhesion)
        check.problem("boundary",
                      "boundary = \"mirrored\" is not implemented with adhesion (its adhesive statistics "
                      "are of the whole extension)",
                      "boundary = \"as_is\", or no interface.adhesion");
      else if (!settings_.residual_topography.empty())
        check.problem("boundary",
                      "boundary = \"mirrored\" with residual_topography would write the mirrored extension",
                      "boundary = \"as_is\", or no residual_topography");
    }
    // The scene's approach-retract path, which an adhesive BEM runs after its loads: on the periodic problem
    // the separation is the mean gap, and a path that turns at or below 0 m has no answer there.
    if (check.scene.approach_retract && check.interface.adhesion &&
        settings_.periodic.value_or(check.surface.grid().periodic) &&
        !(check.scene.approach_retract->turn > 0))
      check.problems.add(0, "approach_retract.to",
                         "the " + std::string(name()) +
                             " method solves the periodic problem, where the separation is "
                             "the mean gap, and a mean gap of " +
                             exact_number(check.scene.approach_retract->turn) +
                             " m or less needs an infinite load",
                         "a separation > 0 m, or periodic = false in the method");
    check_refine_key(check, settings_.refine);
    check_magnitudes(check);
    if (settings_.extrapolate) {
      const Grid& grid = check.surface.grid();
      const Index nx = settings_.refine > 0 ? settings_.refine : grid.nx;
      const Index ny = settings_.refine > 0 ? settings_.refine : grid.ny;
      const bool third_finer =
          uses_third_grid(settings_.error_estimate) && !third_grid_is_coarser(nx, ny, grid.nx, grid.ny);
      if (!grid.periodic)
        check.problem("extrapolate",
                      "the second solve, on twice the points a side, needs Fourier refinement, which needs a "
                      "periodic surface, and this scene's surface is not periodic",
                      "extrapolate = false");
      else if (2 * std::max(nx, ny) > kMaxPointsASide)
        check.problem("extrapolate",
                      "the second solve would need " + std::to_string(2 * std::max(nx, ny)) +
                          " points a side, more than " + std::to_string(kMaxPointsASide),
                      "extrapolate = false, or refine to at most " + std::to_string(kMaxPointsASide / 2));
      else if (third_finer && 4 * std::max(nx, ny) > kMaxPointsASide)
        check.problem("error_estimate",
                      "the third grid of \"gci3\" would need " + std::to_string(4 * std::max(nx, ny)) +
                          " points a side, more than " + std::to_string(kMaxPointsASide) +
                          " (it is half the first grid only when the surface has at most that many points)",
                      "error_estimate = \"gci2\", or refine to at least twice the surface's points a side");
    }
    check_memory(check);
    if (check.interface.adhesion) {
      const AdhesiveMethodRefusal refusal =
          adhesive_method_refusal(settings_.adhesive_method, check.interface.adhesion->model,
                                  settings_.periodic.value_or(check.surface.grid().periodic));
      if (!refusal.reason.empty()) check.problem("adhesive_solver", refusal.reason, refusal.accepted);
    }
    if (check.interface.hardness && check.interface.adhesion)
      check.problems.add(0, "interface.adhesion",
                         "the BEM does not solve adhesion and a hardness together (the plastic cap and the "
                         "attraction are two fixed points it does not couple)",
                         "one of the two, or ignore = [\"hardness\"] or [\"adhesion\"] in [methods." +
                             std::string(name()) + "]");
    // A mean pressure at or above H is full plastic contact: nothing to solve (bem/bem_solver.hpp).
    check_hardness_above_loads(check, ": full plastic contact, which has no solution to compute");
  }

  MethodCurve evaluate(const MethodInputs& in) const override {
    const BemProducts& products = *in.bem;
    const std::vector<ContactStatistics>& stats = products.statistics.at(settings_.connectivity);
    MethodCurve curve;
    // Which solve answers each scene load: the k-th; along a load path, the first step that reached it.
    const std::vector<std::size_t> solve_of = solve_of_load(in.scene.loads, products.load_path);
    std::vector<Real> nodes, corrected, mean_gap, max_pressure, iterations, residual, converged, seconds,
        plastic, plastic_load, path_step;
    for (std::size_t load = 0; load < in.scene.loads.size(); ++load) {
      const std::size_t k = solve_of[load];
      path_step.push_back(static_cast<Real>(k + 1));
      const ContactSolution& s = products.solutions[k];
      curve.area_fraction.push_back(stats[k].area_fraction_corrected);
      curve.separation.push_back(s.separation);
      curve.spots.push_back(static_cast<Real>(stats[k].spots));
      nodes.push_back(stats[k].area_fraction);
      corrected.push_back(stats[k].area_fraction_corrected);
      mean_gap.push_back(stats[k].mean_gap);
      max_pressure.push_back(stats[k].max_pressure);
      iterations.push_back(static_cast<Real>(s.iterations));
      residual.push_back(s.residual);
      // With extrapolate = true a load converged when both of its solves did.
      const bool both = s.converged && (!settings_.extrapolate || products.fine_solutions[k].converged);
      converged.push_back(both ? 1 : 0);
      curve.converged.push_back(both);
      seconds.push_back(s.seconds);
      plastic.push_back(static_cast<Real>(s.plastic_points) / static_cast<Real>(products.points));
      // The share of the load the plastic nodes carry: H x their area over P (each carries H; docs/theory.md
      // section 6, "Plastic area and load").
      if (products.hardness)
        plastic_load.push_back(s.mean_pressure > 0 ? *products.hardness * plastic.back() / s.mean_pressure
                                                   : 0);
    }
    curve.columns = {{"area_fraction_nodes", nodes}, {"area_fraction_corrected", corrected},
                     {"mean_gap", mean_gap},         {"max_pressure", max_pressure},
                     {"iterations", iterations},     {"residual", residual},
                     {"converged", converged},       {"solve_seconds", seconds}};
    // Compared (docs/theory.md section 12): the mean gap is the gap field's mean, already computed with the
    // statistics, and then a typed field rather than the method's own column; the stiffness is the
    // linearised response of each converged state, solved only when the scene compares it.
    if (in.scene.compares(Quantity::mean_gap)) {
      curve.mean_gap = mean_gap;
      curve.columns.erase(curve.columns.begin() + 2);
    }
    if (in.scene.compares(Quantity::stiffness)) curve.stiffness = products.stiffness;
    if (products.hardness) {
      curve.columns.emplace_back("plastic_area_fraction", plastic);  // nodes at p = H / all
      curve.columns.emplace_back("plastic_load_fraction", plastic_load);
    }
    if (!products.load_path.empty()) {
      curve.columns.emplace_back("path_step", path_step);  // the step of the path each row comes from
      add_path_columns(products, curve);
    }
    if (!products.periodic) {
      // What the record's edges carry (bem/contact_statistics.hpp): every non-periodic run reports it.
      std::vector<Real> edge_contact, edge_load;
      for (const ContactStatistics& s : stats) {
        edge_contact.push_back(s.edge_contact_share);
        edge_load.push_back(s.edge_load_share);
      }
      curve.columns.emplace_back("edge_contact_share", edge_contact);
      curve.columns.emplace_back("edge_load_share", edge_load);
    }
    if (settings_.extrapolate) extrapolate(products, in.scene.loads, curve);
    if (settings_.node_area) curve.area_fraction = nodes;
    // The compared perimeter-corrected area's own bar (docs/theory.md section 9.2), where it was calibrated:
    // periodic, without hardness or adhesion (scripts/studies/error_bar.py).
    if (!settings_.extrapolate && !settings_.node_area && products.periodic && !products.hardness &&
        !products.adhesion)
      for (std::size_t k = 0; k < nodes.size(); ++k)
        curve.area_fraction_error.push_back(corrected_area_error(nodes[k], corrected[k]));
    curve.area_fraction_nodes = nodes;
    curve.accepts_unconverged = settings_.allow_unconverged;
    // The boundary as solved (resolve_boundary); the fallback's reason only when this method left it unset.
    BemStage stage{.settings = settings_,
                   .periodic = products.periodic,
                   .as_is_because = settings_.mirrored ? std::string() : products.as_is_because,
                   .hardness = products.hardness,
                   .adhesion = products.adhesion,
                   .load_path = products.load_path,
                   .distributions = std::nullopt,
                   .approach_retract = std::nullopt};
    stage.settings.mirrored = products.mirrored;
    curve.parameters =
        "BEM " + stage.name().substr(4) +
        (settings_.extrapolate ? std::string(", perimeter-corrected area in area_fraction_corrected")
                               : std::string(", area perimeter-corrected")) +
        " (node count in area_fraction_nodes), spots by " + std::to_string(settings_.connectivity) +
        "-connectivity";
    if (settings_.extrapolate)
      curve.parameters +=
          settings_.error_estimate == ErrorEstimate::calibrated3
              ? "; area Richardson-extrapolated at order 1 from the node counts on three grids (" +
                    std::to_string(products.third_nx * products.third_ny) + ", " +
                    std::to_string(products.points) + " and " + std::to_string(products.fine_points) +
                    " nodes), error bar calibrated on the BEM's grid sequences (columns observed_order, "
                    "safety_factor; docs/theory.md section 9.2); spots and separation of the grid on " +
                    std::to_string(products.fine_points) + " nodes"
          : uses_third_grid(settings_.error_estimate)
              ? "; area Richardson-extrapolated at the observed order from the node counts on three grids (" +
                    std::to_string(products.third_nx * products.third_ny) + ", " +
                    std::to_string(products.points) + " and " + std::to_string(products.fine_points) +
                    " nodes), error bar Roache's GCI (factor 1.25, 3 where the order is not observed in "
                    "[0.5, 2]; columns observed_order, safety_factor; docs/theory.md section 9.2); spots and "
                    "separation of the grid on " +
                    std::to_string(products.fine_points) + " nodes"
              : "; area Richardson-extrapolated (order 1) from the node counts on " +
                    std::to_string(products.points) + " and " + std::to_string(products.fine_points) +
                    " nodes, error bar Roache's two-grid GCI 3 |N(2n) - N(n)| (docs/theory.md section 9.2); "
                    "spots and separation of the finer grid";
    if (products.adhesion) add_adhesive_columns(products, in.scene.material.estar, curve);
    if (products.distributions) add_distributions(products, in, curve);
    if (products.approach_retract) {
      curve.approach_retract = products.approach_retract;
      curve.approach_retract_points = products.points;
    }
    return curve;
  }

  // The distributions the stage measured at the scene's reference load, the clusters by this method's
  // connectivity, beside Persson's P(sigma) over the scene surface's spectrum (theories/persson_gap.hpp).
  void add_distributions(const BemProducts& products, const MethodInputs& in, MethodCurve& curve) const {
    const MeasuredDistributions& m = *products.distributions;
    LoadDistributions d{.load = in.scene.distributions->load,
                        .estar = in.scene.material.estar,
                        .q3_integral = persson_q3_integral(fourier_coefficients(in.surface)),
                        .pixel_area = m.pixel_area,
                        .points = m.points,
                        .contact_points = m.contact_points,
                        .mean_pressure = m.mean_pressure,
                        .mean_gap = m.mean_gap,
                        .connectivity = settings_.connectivity,
                        .pressure = m.pressure,
                        .gap = m.gap,
                        .patch_sizes = patch_size_histogram(m.cluster_areas.at(settings_.connectivity),
                                                            in.scene.distributions->bins),
                        .plateau = {},
                        .plateau_hertz = {},
                        .summit = std::nullopt,
                        .summit_note = {}};
    // The plateau models and GW-McCool at the same load, on the same bins (docs/theory.md 12.8).
    add_distribution_theories(
        d, in.surface,
        Topology::for_surface(settings_.connectivity == 8 ? Connectivity::eight : Connectivity::four,
                              in.surface.grid().periodic));
    curve.distributions = std::move(d);
  }

  // Along a load path, one row per step (the report's <label>_path.csv): the load, whether the step loads
  // (+1), unloads (-1) or repeats (0) from the one before (from zero load for the first), and the compared
  // area (as area_fraction of curves.csv), the node count, the plastic fractions, the separation and whether
  // it converged.
  void add_path_columns(const BemProducts& products, MethodCurve& curve) const {
    const std::vector<ContactStatistics>& stats = products.statistics.at(settings_.connectivity);
    const std::size_t steps = products.load_path.size();
    std::vector<Real> step(steps), load(steps), direction(steps), area(steps), nodes(steps), plastic(steps),
        plastic_load(steps), separation(steps), converged(steps);
    for (std::size_t k = 0; k < steps; ++k) {
      const ContactSolution& s = products.solutions[k];
      const Real before = k == 0 ? 0 : products.load_path[k - 1];
      step[k] = static_cast<Real>(k + 1);
      load[k] = products.load_path[k];
      direction[k] = load[k] > before ? 1 : load[k] < before ? -1 : 0;
      nodes[k] = stats[k].area_fraction;
      area[k] = settings_.node_area ? nodes[k] : stats[k].area_fraction_corrected;  // the compared area
      plastic[k] = static_cast<Real>(s.plastic_points) / static_cast<Real>(products.points);
      plastic_load[k] =
          products.hardness && s.mean_pressure > 0 ? *products.hardness * plastic[k] / s.mean_pressure : 0;
      separation[k] = s.separation;
      converged[k] = s.converged ? 1 : 0;
    }
    curve.path_columns = {{"step", step},
                          {"load", load},
                          {"direction", direction},
                          {"area_fraction", area},
                          {"area_fraction_nodes", nodes},
                          {"plastic_area_fraction", plastic},
                          {"plastic_load_fraction", plastic_load},
                          {"separation", separation},
                          {"converged", converged}};
  }

  // The memory of the largest solve, before any work (a 16384^2 refinement with extrapolate = true would
  // otherwise grow for minutes until the kernel kills it). Bytes per point of the whole process, measured as
  // peak resident memory (/usr/bin/time) of `contactbench bem` on 1024^2 and 2048^2 surfaces (the two agree
  // within 7 %): 150 periodic, 175 non-periodic, 115 / 135 in single precision; active_set adds its coarse
  // levels, set arrays and the extended filter's weights and window sums, +94 / +119 (+56 / +66 in single
  // precision; measured the same way on surface A at 2048^2, P/(E* A0) = 0.01: 241, 293, 170 and 197 bytes
  // per point in all; again after its response to a unit load and single-precision weights, 237, 290, 168
  // and 194; with the filter in single precision, 229, 272, 168 and 194). extrapolate = true solves the same
  // loads again on 4 times the points, after the first grid is freed: the finer solve is the peak;
  // error_estimate = "gci3" with a third grid twice the finer: that one is the peak.
  void check_memory(const MethodCheck& check) const {
    const Grid& grid = check.surface.grid();
    const Index nx = settings_.refine > 0 ? settings_.refine : grid.nx;
    const Index ny = settings_.refine > 0 ? settings_.refine : grid.ny;
    const bool third_finer = settings_.extrapolate && uses_third_grid(settings_.error_estimate) &&
                             !third_grid_is_coarser(nx, ny, grid.nx, grid.ny);
    const bool mirrored = resolve_boundary(settings_, settings_.periodic.value_or(grid.periodic),
                                           check.interface.adhesion.has_value())
                              .mirrored;
    const Index side = third_finer ? 4 : settings_.extrapolate || mirrored ? 2 : 1;
    const bool periodic = mirrored || settings_.periodic.value_or(grid.periodic);
    std::uintmax_t per_point =
        settings_.solver.single_precision ? (periodic ? 115 : 135) : (periodic ? 150 : 175);
    if (settings_.solver.solver == SolverKind::active_set)
      per_point += settings_.solver.single_precision ? (periodic ? 56 : 66) : (periodic ? 94 : 119);
    const std::uintmax_t points =
        saturating_product(static_cast<std::uintmax_t>(side * nx), static_cast<std::uintmax_t>(side * ny));
    std::string what =
        "the BEM solve on " + std::to_string(side * nx) + " x " + std::to_string(side * ny) + " points";
    std::uintmax_t bytes = saturating_product(points, per_point);
    std::string accepted =
        "a solve that fits: fewer points (refine), extrapolate = false, boundary = \"as_is\" or precision = "
        "\"single\"";
    // Spread over MPI ranks, the runner says what the ranks on this machine hold together.
    // What rank 0 holds whole beside its slab under mpiexec (docs/mpi.md): the scene's heights unless they
    // stay on the ranks' slabs and no grid is refined (the ranks refine on their slabs from the scene's
    // coefficients, which rank 0 takes from the whole heights with a cached transform: 24 B a point of the
    // scene's grid in all), and a copy of them when the stage solves them whole with another boundary; the
    // pressure and gap it gathers for `fields` or the distributions (the patch's when mirrored).
    const bool refines = settings_.refine > 0 || settings_.extrapolate;
    const bool on_slabs = check.surface.resident() && !refines;
    const auto scene_points = static_cast<std::uintmax_t>(grid.points());
    const std::uintmax_t judged_points = mirrored ? points / 4 : points;
    std::uintmax_t root_bytes = 0;
    if (refines)
      root_bytes = saturating_product(scene_points, 24);
    else if (!on_slabs)
      root_bytes = saturating_sum(saturating_product(scene_points, 8), saturating_product(judged_points, 8));
    if (!settings_.fields.empty() || check.scene.distributions)
      root_bytes = saturating_sum(root_bytes, saturating_product(judged_points, 16));
    if (check.runner)
      if (const auto spread = check.runner->bem_memory(
              settings_.solver,
              Grid{.nx = side * nx, .ny = side * ny, .lx = grid.lx, .ly = grid.ly, .periodic = periodic},
              root_bytes)) {
        bytes = spread->bytes;
        what += " (" + spread->how + ")";
        accepted = "a solve that fits: fewer points (refine), or the ranks spread over more machines";
      }
    try {
      check_fits_in_memory(bytes, what);
    } catch (const Error& e) {
      check.problem(settings_.refine > 0 ? "refine" : "", e.what(), accepted);
    }
  }

  // The solver sums squares of heights, gaps and pressures (core/scales.hpp): each scale of the problem must
  // keep them inside double precision, or the solve ends "converged" on nonsense (heights of 1e290 m: the
  // whole grid in contact after one iteration). And far beyond full contact the pressure is its mean plus a
  // variation of order E* (height range / pixel) that double precision cannot resolve beside that mean: the
  // answer (area 1) is known but no solve reaches the tolerance, so it is refused with the reason.
  void check_magnitudes(const MethodCheck& check) const {
    const Real range = check.surface.height_range();  // from the slabs' extremes when resident
    const Grid& grid = check.surface.grid();
    const Real estar = check.scene.material.estar;
    const std::string accepted = "quantities within 1e-100 to 1e100 of their SI unit";
    // The heights' range and the lateral sizes were checked with the moments, which every run computes before
    // any preflight (check_summable_heights, core/spectrum.hpp); E* and the pressures are the BEM's own.
    if (!within_magnitudes(estar)) check.problem("", magnitude_problem("E*", estar, "Pa"), accepted);
    const Real pixel = std::min(grid.lx / static_cast<Real>(grid.nx), grid.ly / static_cast<Real>(grid.ny));
    const Real slope_scale = range / pixel;  // the height range over one pixel
    for (const Real load : check.scene.loads) {
      if (!within_magnitudes(load * estar))
        check.problem("", magnitude_problem("the mean pressure P/A0 = load E*", load * estar, "Pa"),
                      accepted);
      else if (range > 0 && load > kFullContactResolution * slope_scale)
        check.problem("",
                      "the load P/(E* A0) = " + exact_number(load) + " is more than " +
                          exact_number(kFullContactResolution) +
                          " times the surface's height range per pixel (" + exact_number(slope_scale) +
                          "): full contact, where the pressure's variation about its mean is below double "
                          "precision's resolution and no solve can converge",
                      "loads up to " + exact_number(kFullContactResolution * slope_scale) +
                          " for this surface (the contact area is 1 above that)");
    }
  }

  // docs/theory.md section 9: the node count overestimates the area by a band along the contact edges, a
  // pixel wide: an error of order 1 in the pixel size (measured: scripts/studies/bem_area_order.py). The
  // counts on the grids are extrapolated to the zero pixel, and the error bar is Roache's grid convergence
  // index (bem/grid_convergence.hpp, section 9.2), calibrated by scripts/studies/error_bar.py.
  void extrapolate(const BemProducts& products, const std::vector<Real>& loads, MethodCurve& curve) const {
    const std::vector<ContactStatistics>& coarse = products.statistics.at(settings_.connectivity);
    const std::vector<ContactStatistics>& fine = products.fine_statistics.at(settings_.connectivity);
    const bool three = uses_third_grid(settings_.error_estimate);
    const bool third_coarser = three && products.third_nx * products.third_ny < products.points;
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    std::vector<Real> fine_nodes, fine_corrected, extrapolated, error, fine_iterations, order, factor,
        grid_coarse, grid_medium, grid_fine;
    // The grids behind the bar, points a side (the geometric mean of nx and ny), coarsest first.
    const Real first_side = std::sqrt(static_cast<Real>(products.points));
    const Real third_side = std::sqrt(static_cast<Real>(products.third_nx * products.third_ny));
    for (std::size_t k = 0; k < coarse.size(); ++k) {
      GridConvergence g;
      if (!three) {
        g = grid_convergence_two(coarse[k].area_fraction, fine[k].area_fraction);
      } else {
        const Real third = products.third_statistics.at(settings_.connectivity)[k].area_fraction;
        const Real a = third_coarser ? third : coarse[k].area_fraction;
        const Real b = third_coarser ? coarse[k].area_fraction : fine[k].area_fraction;
        const Real c = third_coarser ? fine[k].area_fraction : third;
        // The finest grid's nodes (the calibrated bar's lattice term) and the load (its band): extrapolate is
        // refused along a load path, so the k-th solve is the k-th scene load.
        const Real finest_points =
            static_cast<Real>(third_coarser ? products.fine_points : products.third_nx * products.third_ny);
        g = settings_.error_estimate == ErrorEstimate::calibrated3
                ? grid_convergence_calibrated(a, b, c, finest_points, loads.at(k))
                : grid_convergence_three(a, b, c);
      }
      fine_nodes.push_back(fine[k].area_fraction);
      fine_corrected.push_back(fine[k].area_fraction_corrected);
      // A negative extrapolation is a grid far from the asymptotic range: no answer rather than a wrong one.
      extrapolated.push_back(g.value > 0 ? g.value : nan);
      error.push_back(g.value > 0 ? g.error : nan);
      order.push_back(g.order);
      factor.push_back(g.factor);
      grid_coarse.push_back(third_coarser ? third_side : first_side);
      grid_medium.push_back(third_coarser ? first_side : 2 * first_side);
      grid_fine.push_back(third_coarser ? 2 * first_side : third_side);
      fine_iterations.push_back(static_cast<Real>(products.fine_solutions[k].iterations));
      curve.separation[k] = products.fine_solutions[k].separation;
      curve.spots[k] = static_cast<Real>(fine[k].spots);
    }
    curve.area_fraction = extrapolated;
    curve.area_fraction_error = error;
    curve.summary_columns = {"area_fraction_extrapolated"};
    curve.columns.emplace_back("area_fraction_nodes_fine", fine_nodes);
    curve.columns.emplace_back("area_fraction_corrected_fine", fine_corrected);
    curve.columns.emplace_back("area_fraction_extrapolated", extrapolated);
    curve.columns.emplace_back("area_fraction_error", error);
    curve.columns.emplace_back("observed_order", order);  // NaN: two grids, or no monotone convergence
    curve.columns.emplace_back("safety_factor", factor);
    curve.columns.emplace_back("grid_coarse", grid_coarse);
    curve.columns.emplace_back("grid_medium", grid_medium);
    if (three) curve.columns.emplace_back("grid_fine", grid_fine);
    curve.columns.emplace_back("iterations_fine", fine_iterations);
  }

 private:
  BemSettings settings_ = default_settings(bem_settings());  // every key, as read
};

}  // namespace

std::unique_ptr<Method> make_bem_method() {
  return std::make_unique<BemMethod>();
}

}  // namespace contactbench
