// The boundary-element ground truth as a method of a scene: Polonsky-Keer (bem/polonsky_keer.hpp) at every
// scene load, its area perimeter-corrected (bem/contact_statistics.hpp; docs/theory.md section 6).
#include <algorithm>
#include <limits>
#include <memory>

#include "contactbench/app/methods/method.hpp"
#include "contactbench/app/methods/refine_key.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/scene_toml.hpp"
#include "contactbench/app/stages.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

class BemMethod final : public Method {
 public:
  std::string_view name() const override { return "bem"; }
  std::string compared_area() const override {
    return "area_fraction_corrected (contact nodes less the perimeter band of Yastrebov, Anciaux and "
           "Molinari 2017; the node count is area_fraction_nodes)";
  }

  // The schema of [methods.<label>] with method = "bem": one key, one field of BemStage (whose member
  // initialisers are the defaults).
  void read(const Section& s, const SceneContext& context) override {
    s.reject_unknown({"method", "refine", "tolerance", "max_iterations", "periodic", "hardness", "precision",
                      "fields", "connectivity", "solver"});
    std::vector<std::string_view> solvers(solver_names().begin(), solver_names().end());
    if (const auto name = s.choice("solver", solvers)) solve_.solver = solver_kind(*name);
    solve_.refine = read_refine_key(s, context, solve_.refine);
    const auto precision = s.choice("precision", {"double", "single"});
    solve_.single_precision = precision == "single";
    // Single precision resolves a relative change of about 1e-7: its default is the smallest it accepts.
    const Real smallest = solve_.single_precision ? kSinglePrecisionTolerance : 0;
    if (solve_.single_precision) solve_.tolerance = kSinglePrecisionTolerance;
    solve_.tolerance =
        s.number("tolerance", false,
                 {[smallest](Real v) { return v > 0 && v < 1 && v >= smallest; },
                  solve_.single_precision ? "a number in [1e-06, 1) (single precision cannot resolve less)"
                                          : "a number in (0, 1)"})
            .value_or(solve_.tolerance);
    solve_.max_iterations = static_cast<Index>(
        s.integer("max_iterations", false, int_range(1, std::numeric_limits<std::int32_t>::max()))
            .value_or(solve_.max_iterations));
    periodic_ = s.boolean("periodic");
    solve_.hardness = s.number("hardness", false, positive("[Pa]"));
    // Relative to the scene file's folder, as the surface file is; stored resolved.
    if (const auto fields =
            s.string("fields", false,
                     "a path prefix for the per-load pressure and gap files (relative: to the "
                     "scene file's folder)"))
      solve_.fields = (context.folder / *fields).lexically_normal().string();
    connectivity_ = static_cast<int>(
        s.integer("connectivity", false, {[](std::int64_t v) { return v == 4 || v == 8; }, "4, 8"})
            .value_or(connectivity_));
  }

  void write(SceneKeys& keys) const override {
    keys.put("refine", std::int64_t{solve_.refine});
    keys.put("tolerance", solve_.tolerance);
    keys.put("max_iterations", std::int64_t{solve_.max_iterations});
    if (periodic_) keys.put("periodic", *periodic_);
    if (solve_.hardness) keys.put("hardness", *solve_.hardness);
    keys.put("precision", solve_.single_precision ? "single" : "double");
    if (!solve_.fields.empty()) keys.put("fields", solve_.fields);
    keys.put("connectivity", std::int64_t{connectivity_});
    keys.put("solver", std::string(solver_name(solve_.solver)));
  }

  MethodNeeds needs(const SceneContext& context) const override {
    BemStage stage = solve_;
    stage.periodic = periodic_.value_or(context.surface_periodic);
    return {.moments = false, .sweep = std::nullopt, .bem = stage, .bem_connectivity = connectivity_};
  }

  void preflight(const MethodCheck& check) const override {
    if (!solve_.fields.empty()) {
      // Field files are never written over a device, a link or a folder (app/output.hpp).
      try {
        check_output_prefix(solve_.fields, "fields");
        for (std::size_t k = 0; k < check.scene.loads.size(); ++k)
          for (const char* field : {"pressure", "gap"})
            check_replaceable_file(field_path(solve_.fields, k + 1, field));
      } catch (const Error& e) {
        check.problem("fields", e.what(), "a prefix of new or regular files in an existing folder");
      }
    }
    check_refine_key(check, solve_.refine);
    if (solve_.hardness) {
      // A mean pressure at or above H is full plastic contact: nothing to solve (bem/polonsky_keer.hpp).
      std::vector<std::string> refused;
      for (std::size_t k = 0; k < check.scene.loads.size(); ++k)
        if (check.scene.loads[k] * check.scene.material.estar >= *solve_.hardness)
          refused.push_back(exact_number(check.scene.loads[k]) + " (load " + std::to_string(k + 1) + ")");
      if (!refused.empty())
        check.problem("hardness",
                      "the hardness " + exact_number(*solve_.hardness) +
                          " Pa is at or below the mean pressure " + "P/A0 = load E* of the loads " +
                          join(refused) + ": full plastic contact, which has no solution to compute",
                      "a hardness above " +
                          exact_number(check.scene.loads.back() * check.scene.material.estar) +
                          " Pa (the largest load times E*), or loads below hardness/E*");
    }
  }

  MethodCurve evaluate(const MethodInputs& in) const override {
    const BemProducts& products = *in.bem;
    const std::vector<ContactStatistics>& stats = products.statistics.at(connectivity_);
    MethodCurve curve;
    std::vector<Real> nodes, corrected, mean_gap, max_pressure, iterations, residual, converged, seconds,
        plastic;
    for (std::size_t k = 0; k < in.scene.loads.size(); ++k) {
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
      converged.push_back(s.converged ? 1 : 0);
      seconds.push_back(s.seconds);
      plastic.push_back(static_cast<Real>(s.plastic_points) / static_cast<Real>(products.points));
    }
    curve.columns = {{"area_fraction_nodes", nodes}, {"area_fraction_corrected", corrected},
                     {"mean_gap", mean_gap},         {"max_pressure", max_pressure},
                     {"iterations", iterations},     {"residual", residual},
                     {"converged", converged},       {"solve_seconds", seconds}};
    if (solve_.hardness) curve.columns.emplace_back("plastic_fraction", plastic);  // nodes at p = H / all
    BemStage stage = solve_;
    stage.periodic = products.periodic;
    curve.parameters = "BEM " + stage.name().substr(4) +
                       ", area perimeter-corrected (node count in area_fraction_nodes), spots by " +
                       std::to_string(connectivity_) + "-connectivity";
    return curve;
  }

 private:
  BemStage solve_;                // every solver key; periodic resolved against the surface in needs()
  std::optional<bool> periodic_;  // default: the surface's own periodicity
  int connectivity_ = 4;          // for counting contact spots
};

}  // namespace

std::unique_ptr<Method> make_bem_method() {
  return std::make_unique<BemMethod>();
}

}  // namespace contactbench
