#include "contactbench/app/comparison.hpp"

#include <cmath>
#include <limits>

namespace contactbench {

Comparison compare(const SceneReport& report) {
  Comparison comparison;
  comparison.reference = report.scene.reference;
  comparison.rms_gradient = report.moments.rms_gradient();
  const std::vector<Real>& loads = report.loads();
  comparison.kappa_load = loads.empty() ? 0 : loads.front();
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const MethodResult* reference = nullptr;
  for (const MethodResult& m : report.methods)
    if (m.label == comparison.reference) reference = &m;
  // kappa = (A/A0) gbar / (P/(E* A0)): p/(E* gbar) = (P/(E* A0)) / gbar.
  const auto kappa = [&](Real area_fraction) {
    return area_fraction * comparison.rms_gradient / comparison.kappa_load;
  };

  if (reference)
    for (std::size_t k = 0; k < reference->curve.area_fraction_error.size(); ++k)
      comparison.reference_uncertainty.push_back(reference->curve.area_fraction_error[k] /
                                                 reference->curve.area_fraction[k]);

  for (const MethodResult& m : report.methods) {
    MethodComparison c;
    c.label = m.label;
    c.kappa = m.curve.area_fraction.empty() ? nan : kappa(m.curve.area_fraction.front());
    if (!m.curve.area_fraction_nodes.empty()) c.kappa_nodes = kappa(m.curve.area_fraction_nodes.front());
    if (reference) {
      Real sum_squares = 0, largest = 0;
      std::size_t counted = 0;
      for (std::size_t k = 0; k < loads.size(); ++k) {
        const Real error = m.curve.area_fraction[k] / reference->curve.area_fraction[k] - 1;
        c.relative_error.push_back(std::isfinite(error) ? error : nan);
        if (!std::isfinite(error)) continue;
        sum_squares += error * error;
        largest = std::max(largest, std::abs(error));
        ++counted;
      }
      c.max_abs_relative_error = counted ? largest : nan;
      c.rms_relative_error = counted ? std::sqrt(sum_squares / static_cast<Real>(counted)) : nan;
    } else {
      c.max_abs_relative_error = c.rms_relative_error = nan;
    }
    comparison.methods.push_back(std::move(c));
  }
  return comparison;
}

}  // namespace contactbench
