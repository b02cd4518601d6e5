// The contact modulus E* (docs/theory.md section 0): one elastic body against a rigid one, or two elastic
// bodies.
#pragma once

#include <cmath>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// Throws Error naming `what` unless E > 0 (finite) and -1 < nu < 0.5 (a stable isotropic solid).
inline void validate_elastic_constants(Real youngs_modulus, Real poisson_ratio, const std::string& what) {
  if (!(std::isfinite(youngs_modulus) && youngs_modulus > 0))
    throw Error(what + ": Young's modulus E must be finite and > 0 Pa, got " +
                std::to_string(youngs_modulus));
  if (!(poisson_ratio > -1 && poisson_ratio < 0.5))
    throw Error(what + ": Poisson's ratio nu must lie in (-1, 0.5), got " + std::to_string(poisson_ratio));
}

// E* = E/(1 - nu^2): an elastic body against a rigid one.
inline Real contact_modulus(Real youngs_modulus, Real poisson_ratio) {
  validate_elastic_constants(youngs_modulus, poisson_ratio, "material");
  return youngs_modulus / (1 - poisson_ratio * poisson_ratio);
}

// Two elastic bodies: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (docs/theory.md section 0). Not E/(2(1 - nu^2)),
// which is the special case of two identical bodies.
inline Real composite_modulus(Real e1, Real nu1, Real e2, Real nu2) {
  validate_elastic_constants(e1, nu1, "first body");
  validate_elastic_constants(e2, nu2, "second body");
  return 1 / ((1 - nu1 * nu1) / e1 + (1 - nu2 * nu2) / e2);
}

}  // namespace contactbench
