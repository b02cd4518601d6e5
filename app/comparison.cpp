#include "contactbench/app/comparison.hpp"

#include <cmath>
#include <limits>

namespace contactbench {

namespace {

const Real nan = std::numeric_limits<Real>::quiet_NaN();

struct Errors {
  std::vector<Real> relative;
  Real max_abs = nan, rms = nan;
};

// value / reference - 1 load by load (NaN where either has none), and its largest magnitude and rms over
// the loads where both answer.
Errors relative_errors(const std::vector<Real>& values, const std::vector<Real>& reference) {
  Errors e;
  Real sum_squares = 0, largest = 0;
  std::size_t counted = 0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const Real error = values[k] / reference[k] - 1;
    e.relative.push_back(std::isfinite(error) ? error : nan);
    if (!std::isfinite(error)) continue;
    sum_squares += error * error;
    largest = std::max(largest, std::abs(error));
    ++counted;
  }
  if (counted) {
    e.max_abs = largest;
    e.rms = std::sqrt(sum_squares / static_cast<Real>(counted));
  }
  return e;
}

}  // namespace

Comparison compare(const SceneReport& report) {
  Comparison comparison;
  comparison.reference = report.scene.reference;
  comparison.rms_gradient = report.moments.rms_gradient();
  const std::vector<Real>& loads = report.loads();
  comparison.kappa_load = loads.empty() ? 0 : loads.front();
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
      Errors e = relative_errors(m.curve.area_fraction, reference->curve.area_fraction);
      c.relative_error = std::move(e.relative);
      c.max_abs_relative_error = e.max_abs;
      c.rms_relative_error = e.rms;
    } else {
      c.max_abs_relative_error = c.rms_relative_error = nan;
    }
    for (const Quantity quantity : report.scene.compare) {
      if (quantity == Quantity::area) continue;
      QuantityComparison q;
      q.quantity = quantity;
      q.given = !m.curve.values(quantity).empty();
      q.max_abs_relative_error = q.rms_relative_error = nan;
      if (q.given && reference && !reference->curve.values(quantity).empty()) {
        Errors e = relative_errors(m.curve.values(quantity), reference->curve.values(quantity));
        q.relative_error = std::move(e.relative);
        q.max_abs_relative_error = e.max_abs;
        q.rms_relative_error = e.rms;
      }
      c.quantities.push_back(std::move(q));
    }
    comparison.methods.push_back(std::move(c));
  }
  return comparison;
}

}  // namespace contactbench
