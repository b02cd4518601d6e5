#include "contactbench/app/methods/plastic_theory_method.hpp"

#include <algorithm>

#include "contactbench/app/problems.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/scene_text.hpp"
#include "contactbench/app/section.hpp"

namespace contactbench {

void check_hardness_against_loads(const MethodCheck& check) {
  check_hardness_above_loads(
      check, " for " + check.key + ": the whole nominal area would be plastic (A/A0 = P/(H A0) >= 1)");
}

void PlasticTheoryMethod::read(const Section& s, const SceneContext& context) {
  s.reject_unknown({"method"});
  hardness_ = context.interface.hardness;
}

void PlasticTheoryMethod::write(SceneKeys&) const {}

MethodNeeds PlasticTheoryMethod::needs(const SceneContext&) const {
  return {.moments = true, .sweep = std::nullopt, .bem = std::nullopt, .bem_connectivity = 4};
}

PlasticTheoryInputs PlasticTheoryMethod::inputs(const Scene& scene, const SceneSurface& surface) const {
  PlasticTheoryInputs in;
  if (hardness_) in.hardness_over_estar = *hardness_ / scene.material.estar;
  if (scene.material.poisson_ratio) in.poisson_ratio = *scene.material.poisson_ratio;
  in.nominal_area = surface.grid().nominal_area();
  in.surface = &surface;
  return in;
}

void PlasticTheoryMethod::preflight(const MethodCheck& check) const {
  check_hardness_against_loads(check);
  if (check.interface.hardness &&
      std::any_of(check.scene.loads.begin(), check.scene.loads.end(),
                  [&](Real load) { return load * check.scene.material.estar >= *check.interface.hardness; }))
    return;  // said once above; the theory would only repeat it
  const PlasticTheoryInputs in = inputs(check.scene, check.surface);
  report_loads_the_theory_refuses(
      check, [&](Real load) { curve_(check.moments, std::span<const Real>(&load, 1), in); });
}

MethodCurve PlasticTheoryMethod::evaluate(const MethodInputs& in) const {
  const PlasticCurve plastic = curve_(in.moments, in.scene.loads, inputs(in.scene, in.surface));
  MethodCurve curve = MethodCurve::from(plastic.curve, in.scene.loads);
  curve.columns.emplace_back("plastic_area_fraction", plastic.plastic_area_fraction);
  curve.columns.emplace_back("plastic_load_fraction", plastic.plastic_load_fraction);
  return curve;
}

}  // namespace contactbench
