#include "contactbench/theories/isotropic_moments.hpp"

#include <cmath>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/number_text.hpp"

namespace contactbench {
namespace {

void check_moment(Real value, std::string_view name, std::string_view method) {
  if (!(std::isfinite(value) && value > 0))
    throw Error(std::string(method) + ": the spectral moment " + std::string(name) +
                " must be finite and > 0, got " + format_number(value));
}

void check_isotropy(Real x, Real y, std::string_view name, std::string_view method) {
  const Real ratio = x / y;
  if (std::abs(ratio - 1) > kMaxAnisotropy)
    throw Error(std::string(method) + ": the surface is anisotropic: " + std::string(name) +
                "x = " + format_number(x) + ", " + std::string(name) + "y = " + format_number(y) + ", " +
                std::string(name) + "x/" + std::string(name) + "y = " + format_number(ratio) +
                " differs from 1 by more than " + format_number(100 * kMaxAnisotropy) +
                " %; the theory is for isotropic surfaces and is not applied to this one");
}

}  // namespace

Real isotropic_m2(const SpectralMoments& m, std::string_view method) {
  check_moment(m.m2x, "m2x", method);
  check_moment(m.m2y, "m2y", method);
  check_isotropy(m.m2x, m.m2y, "m2", method);
  return 0.5 * (m.m2x + m.m2y);
}

IsotropicMoments isotropic_moments(const SpectralMoments& m, std::string_view method) {
  check_moment(m.m0, "m0", method);
  const Real m2 = isotropic_m2(m, method);
  check_moment(m.m4x, "m4x", method);
  check_moment(m.m4y, "m4y", method);
  check_isotropy(m.m4x, m.m4y, "m4", method);
  return {.m0 = m.m0, .m2 = m2, .m4 = 0.5 * (m.m4x + m.m4y)};
}

std::string describe(const IsotropicMoments& m) {
  return "profile moments, means of x and y: m0 = " + format_number(m.m0) +
         " m^2, m2 = " + format_number(m.m2) + ", m4 = " + format_number(m.m4) +
         " 1/m^2, alpha = m0 m4/m2^2 = " + format_number(m.m0 * m.m4 / (m.m2 * m.m2));
}

}  // namespace contactbench
