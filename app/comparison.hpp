// Every method's curve judged against the scene's reference at the reference's loads (docs/architecture.md,
// data flow): the relative error in A/A0, and the areal kappa at the smallest load (docs/theory.md section
// 0).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contactbench/app/scene_run.hpp"

namespace contactbench {

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
