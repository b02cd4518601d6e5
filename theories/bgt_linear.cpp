#include "contactbench/theories/bgt_linear.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "contactbench/theories/isotropic_moments.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/requested_loads.hpp"

namespace contactbench {

// Bush, Gibson & Thomas (1975), small-load limit, docs/theory.md section 5: A/A0 = sqrt(pi) P/(E* A0
// sqrt(m2)).
Real bgt_linear_area_fraction(Real load, Real m2) {
  return std::sqrt(std::numbers::pi / m2) * load;
}

Real bgt_linear_full_contact_load(Real m2) {
  return std::sqrt(m2 / std::numbers::pi);
}

LoadAreaCurve bgt_linear_curve(const SpectralMoments& moments, std::span<const Real> loads) {
  const auto start = std::chrono::steady_clock::now();
  const Real m2 = isotropic_m2(moments, "bgt_linear");
  validate_loads(loads, "bgt_linear");
  LoadAreaCurve curve;
  curve.method = "bgt_linear";
  curve.parameters = "profile m2 = mean of m2x and m2y = " + format_number(m2) +
                     "; A/A0 = sqrt(pi) P/(E* A0 sqrt(m2)) (BGT small-load limit, not the full BGT model)";
  bool capped = false;
  for (const Real load : loads) {
    const Real area = bgt_linear_area_fraction(load, m2);
    capped = capped || area > 1;
    curve.load.push_back(load);
    curve.area_fraction.push_back(std::min<Real>(area, 1));
    curve.separation.push_back(std::numeric_limits<Real>::quiet_NaN());
    curve.spots.push_back(std::numeric_limits<Real>::quiet_NaN());
  }
  if (capped)
    curve.parameters +=
        "; capped at A/A0 = 1 for loads >= " + format_number(bgt_linear_full_contact_load(m2)) +
        " (the law exceeds 1 beyond)";
  curve.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return curve;
}

}  // namespace contactbench
