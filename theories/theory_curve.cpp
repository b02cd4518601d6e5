#include "contactbench/theories/theory_curve.hpp"

#include <cmath>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/requested_loads.hpp"

namespace contactbench {

TheoryCurve::TheoryCurve(std::string method) : start_(std::chrono::steady_clock::now()) {
  curve_.method = std::move(method);
}

void TheoryCurve::check_request(std::span<const Real> loads, std::optional<Real> nominal_area) const {
  validate_loads(loads, curve_.method);
  if (nominal_area && !(std::isfinite(*nominal_area) && *nominal_area > 0))
    throw Error(curve_.method + ": the nominal area must be finite and > 0 m^2, got " +
                format_number(*nominal_area));
}

void TheoryCurve::add(Real load, Real area_fraction, Real separation, Real spots) {
  curve_.load.push_back(load);
  curve_.area_fraction.push_back(area_fraction);
  curve_.separation.push_back(separation);
  curve_.spots.push_back(spots);
}

LoadAreaCurve TheoryCurve::finish(std::string parameters) {
  curve_.parameters = std::move(parameters);
  curve_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return std::move(curve_);
}

std::string profile_m2_text(Real m2) {
  return "profile m2 = mean of m2x and m2y = " + format_number(m2);
}

std::string spots_text(std::optional<Real> nominal_area) {
  return nominal_area ? "; spots = N/A0 x A0 with A0 = " + format_number(*nominal_area) + " m^2"
                      : "; spots not given (NaN): no nominal area";
}

}  // namespace contactbench
