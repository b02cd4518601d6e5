#include "contactbench/theories/bgt_linear.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "contactbench/theories/isotropic_moments.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/theory_curve.hpp"

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
  TheoryCurve curve("bgt_linear");
  const Real m2 = isotropic_m2(moments, curve.method());
  curve.check_request(loads);
  bool capped = false;
  for (const Real load : loads) {
    const Real area = bgt_linear_area_fraction(load, m2);
    capped = capped || area > 1;
    curve.add(load, std::min<Real>(area, 1));
  }
  std::string parameters =
      profile_m2_text(m2) +
      "; A/A0 = sqrt(pi) P/(E* A0 sqrt(m2)) (BGT small-load limit, not the full BGT model)";
  if (capped)
    parameters += "; capped at A/A0 = 1 for loads >= " + format_number(bgt_linear_full_contact_load(m2)) +
                  " (the law exceeds 1 beyond)";
  return curve.finish(std::move(parameters));
}

}  // namespace contactbench
