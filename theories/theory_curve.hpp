// What every analytic theory's curve does besides its formula: the curve named after the method, the request
// checked (the loads, and the nominal area where spots are counted), one row per load, and the wall time
// counted from the start.
#pragma once

#include <chrono>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include "contactbench/core/load_area_curve.hpp"

namespace contactbench {

// Theories that solve their separation for each load (GW, BGT) find the root in ln P to this absolute
// tolerance, which is 1e-13 relative in the load (the requirement is 1e-12).
inline constexpr Real kLogLoadTolerance = 1e-13;

class TheoryCurve {
 public:
  // Starts the clock: the curve's seconds count from here.
  explicit TheoryCurve(std::string method);

  const std::string& method() const { return curve_.method; }

  // Refuses (Error naming the method) loads that are not finite, > 0 and ascending (validate_loads), and a
  // nominal area that is given but not finite and > 0.
  void check_request(std::span<const Real> loads, std::optional<Real> nominal_area = std::nullopt) const;

  // One row; NaN where the theory has no separation or no spot count.
  void add(Real load, Real area_fraction, Real separation = std::numeric_limits<Real>::quiet_NaN(),
           Real spots = std::numeric_limits<Real>::quiet_NaN());

  // The curve with its parameters text and the wall time since construction.
  LoadAreaCurve finish(std::string parameters);

 private:
  std::chrono::steady_clock::time_point start_;
  LoadAreaCurve curve_;
};

// The parameters text of the theories that take the profile m2 of an isotropic surface.
std::string profile_m2_text(Real m2);

// The parameters text saying how spots were counted: "; spots = N/A0 x A0 with A0 = ... m^2", or that they
// were not (no nominal area).
std::string spots_text(std::optional<Real> nominal_area);

}  // namespace contactbench
