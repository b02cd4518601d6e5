// The multi-plateaus model of Wang, Liang and Yan as a method of a scene (theories/plateau_model.hpp;
// docs/theory.md section 4): one sweep of the surface, the model's load at each level, read at the loads.
#include "contactbench/app/methods/plateau_method.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include "contactbench/app/methods/refine_key.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/section.hpp"
#include "contactbench/theories/plateau_model.hpp"

namespace contactbench {

namespace {}  // namespace

std::string PlateauMethod::compared_area() const {
  return "the bearing area of {h > z}, a node count (also in area_fraction_nodes)";
}

void PlateauMethod::read(const Section& s, const SceneContext& context) {
  s.reject_unknown({"method", "connectivity", "levels", "periodic", "refine", "write_levels"});
  connectivity_ = static_cast<int>(s.integer("connectivity", false,
                                             {[](std::int64_t v) { return connectivity_of(v).has_value(); },
                                              std::string(kConnectivityAccepted)})
                                       .value_or(connectivity_));
  periodic_ = s.boolean("periodic");
  write_levels_ = s.boolean("write_levels").value_or(write_levels_);
  refine_ = read_refine_key(s, context, refine_);
  if (const toml::node* node = s.find("levels")) {
    if (const auto* text = node->as_string()) {
      if (const auto named = SweepLevels::named(text->get()))
        levels_ = *named;
      else
        s.problem("levels", "unknown levels \"" + text->get() + "\"", SweepLevels::kAccepted);
    } else if (const auto* count = node->as_integer()) {
      if (const auto counted = SweepLevels::counted(count->get()))
        levels_ = *counted;
      else
        s.problem("levels", "out of range: got " + std::to_string(count->get()), SweepLevels::kAccepted);
    } else {
      s.wrong_type("levels", "a string or an integer", SweepLevels::kAccepted);
    }
  }
}

void PlateauMethod::write(SceneKeys& keys) const {
  keys.put("connectivity", std::int64_t{connectivity_});
  switch (levels_.kind) {
    case SweepLevels::Kind::exact:
      keys.put("levels", "exact");
      break;
    case SweepLevels::Kind::paper:  // read() makes only the paper's own count
      keys.put("levels", "paper");
      break;
    case SweepLevels::Kind::uniform:
      keys.put("levels", std::int64_t{levels_.count});
      break;
  }
  if (periodic_) keys.put("periodic", *periodic_);
  keys.put("refine", std::int64_t{refine_});
  if (write_levels_) keys.put("write_levels", true);  // absent means false: scenes without it read as before
}

MethodNeeds PlateauMethod::needs(const SceneContext& context) const {
  const Connectivity connectivity = connectivity_ == 8 ? Connectivity::eight : Connectivity::four;
  return {.moments = false,
          .sweep = SweepStage{.topology = Topology::for_surface(connectivity,
                                                                periodic_.value_or(context.surface_periodic)),
                              .levels = levels_,
                              .refine = refine_},
          .bem = std::nullopt,
          .bem_connectivity = 4};
}

void PlateauMethod::preflight(const MethodCheck& check) const {
  check_refine_key(check, refine_);
}

void PlateauMethod::complete(MethodCurve& curve, const MethodInputs& in) const {
  // The cut level's mean gap (docs/theory.md section 12.5): outside the spots the surface is undeformed,
  // on them the gap is 0, so u-bar = mean of (z - h)+ over the scene's surface, z the curve's separation.
  if (in.scene.compares(Quantity::mean_gap)) {
    curve.mean_gap = in.surface.mean_gaps(curve.separation);
  }
  if (refine_ > 0)
    curve.parameters +=
        ", on the surface Fourier-refined to " + std::to_string(refine_) + " x " + std::to_string(refine_);
  if (write_levels_) curve.levels = in.sweep->sweep;
}

MethodCurve PlateauMethod::evaluate(const MethodInputs& in) const {
  MethodCurve curve = MethodCurve::from(
      plateau_curve_at_loads(in.sweep->sweep, in.sweep->model, in.scene.loads), in.scene.loads);
  complete(curve, in);
  // The model's own dP/dd (its eq. 2): K = 2 E* sqrt(A_c N / pi) / A0 with the level's area and spots.
  if (in.scene.compares(Quantity::stiffness)) {
    const Real a0 = in.surface.grid().nominal_area(), estar = in.scene.material.estar;
    for (std::size_t k = 0; k < curve.area_fraction.size(); ++k)
      curve.stiffness.push_back(2 * estar * std::sqrt(curve.area_fraction[k] * curve.spots[k] / (pi * a0)));
  }
  curve.area_fraction_nodes = curve.area_fraction;  // the model's area is the bearing area, a node count
  curve.columns.emplace_back("area_fraction_nodes", curve.area_fraction);
  return curve;
}

std::unique_ptr<Method> make_plateau_method() {
  return std::make_unique<PlateauMethod>();
}

}  // namespace contactbench
