#include "contactbench/theories/jkr_sphere.hpp"

#include <cmath>

#include "contactbench/core/error.hpp"

namespace contactbench {

// Johnson, Kendall & Roberts (1971) in Johnson & Greenwood's units (1997, their JKR limit λ → ∞).
JkrState jkr_at_radius(Real a) {
  if (!(std::isfinite(a) && a > 0)) throw Error("JKR: the contact radius must be finite and > 0");
  return {a * a * a - std::sqrt(6 * a * a * a), a * a - std::sqrt(8 * a / 3), 2 * a - std::sqrt(2 / (3 * a))};
}

// δ̄ = ā² − √(8ā/3) = 0 ⇔ ā³ = 8/3.
Real jkr_radius_at_touch() {
  return std::cbrt(8.0 / 3.0);
}

// 2ā = √(2/(3ā)) ⇔ ā³ = 1/6.
Real jkr_radius_at_separation() {
  return std::cbrt(1.0 / 6.0);
}

}  // namespace contactbench
