// Every method's curve judged against the scene's reference at the reference's loads (docs/architecture.md,
// data flow): the relative error in A/A0, and the areal kappa at the smallest load (docs/theory.md section
// 0); and, for each further quantity the scene compares (the mean gap, the stiffness: Scene::compare,
// docs/theory.md section 12), the relative error where both the method and the reference give it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contactbench/app/compared_quantity.hpp"
#include "contactbench/app/scene_run.hpp"

namespace contactbench {

// One compared quantity other than the area, for one method.
struct QuantityComparison {
  Quantity quantity = Quantity::mean_gap;
  // Whether the method gives the quantity at all (MethodCurve: a non-empty vector); when not, the tables
  // say "n/a" and there are no errors.
  bool given = false;
  // value / (the reference's value) - 1 at each load; NaN where either has no answer; empty when the method
  // or the reference does not give the quantity or the scene has no reference.
  std::vector<Real> relative_error;
  Real max_abs_relative_error = 0;  // over the loads where both answer (NaN if none)
  Real rms_relative_error = 0;
};

struct MethodComparison {
  std::string label;
  // A/A0 / (A/A0 of the reference) - 1 at each of the report's loads, each method's compared area
  // (MethodResult::compared_area); NaN where either has no answer. Empty when the
  // scene has no reference.
  std::vector<Real> relative_error;
  Real max_abs_relative_error = 0;  // over the loads where both answer (NaN if none)
  Real rms_relative_error = 0;
  // Areal kappa = (A/A0) / (p/(E* gbar)) at the smallest load, gbar = sqrt(m2x + m2y) of the scene's surface.
  Real kappa = 0;
  std::optional<Real> kappa_nodes;  // of the node count, when the method has one (MethodCurve)
  // The scene's other compared quantities, in Scene::compare's order (empty when it compares the area only).
  std::vector<QuantityComparison> quantities;
};

struct Comparison {
  std::string reference;                  // label, "" when the scene has none
  Real rms_gradient = 0;                  // gbar
  Real kappa_load = 0;                    // the smallest load P/(E* A0), where kappa is evaluated
  std::vector<MethodComparison> methods;  // in the report's order
  // The reference's own discretisation error relative to its area, at each load (its
  // MethodCurve::area_fraction_error / its area: a BEM with extrapolate = true); empty when it has none.
  std::vector<Real> reference_uncertainty;
};

Comparison compare(const SceneReport& report);

}  // namespace contactbench
