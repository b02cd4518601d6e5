#include "contactbench/theories/load_solver.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "contactbench/core/error.hpp"

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

std::string format_number(Real value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

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

void validate_loads(std::span<const Real> loads, std::string_view method) {
  for (std::size_t i = 0; i < loads.size(); ++i) {
    if (!(std::isfinite(loads[i]) && loads[i] > 0))
      throw Error(std::string(method) + ": a load P/(E* A0) must be finite and > 0, got " +
                  format_number(loads[i]) + " at position " + std::to_string(i));
    if (i > 0 && loads[i] < loads[i - 1])
      throw Error(std::string(method) + ": loads must be ascending, got " + format_number(loads[i]) +
                  " at position " + std::to_string(i) + " after " + format_number(loads[i - 1]));
  }
}

Real find_root(const std::function<Real(Real)>& f, Real a, Real b, Real fa, Real fb, Real f_tolerance,
               Real x_tolerance) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  if (fa == 0) return a;
  if (fb == 0) return b;
  if ((fa > 0) == (fb > 0))
    throw Error("find_root: the interval [" + format_number(a) + ", " + format_number(b) +
                "] does not bracket a root (f = " + format_number(fa) + ", " + format_number(fb) + ")");
  // c is the other end of the bracket [b, c]; b is the best estimate, a the previous one.
  Real c = a, fc = fa;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const Real previous_step = b - a;
    if (std::abs(fc) < std::abs(fb)) {
      a = b, b = c, c = a;
      fa = fb, fb = fc, fc = fa;
    }
    const Real tolerance = 2 * eps * std::abs(b) + 0.5 * x_tolerance;
    Real step = 0.5 * (c - b);
    if (std::abs(step) <= tolerance || std::abs(fb) <= f_tolerance) return b;
    if (std::abs(previous_step) >= tolerance && std::abs(fa) > std::abs(fb)) {
      // Secant (two points) or inverse quadratic interpolation (three), accepted only inside the bracket and
      // when it shrinks faster than bisection would.
      const Real cb = c - b;
      Real p, q;
      if (a == c) {
        const Real t1 = fb / fa;
        p = cb * t1;
        q = 1 - t1;
      } else {
        const Real qa = fa / fc, t1 = fb / fc, t2 = fb / fa;
        p = t2 * (cb * qa * (qa - t1) - (b - a) * (t1 - 1));
        q = (qa - 1) * (t1 - 1) * (t2 - 1);
      }
      if (p > 0)
        q = -q;
      else
        p = -p;
      if (p < 0.75 * cb * q - 0.5 * std::abs(tolerance * q) && p < std::abs(0.5 * previous_step * q))
        step = p / q;
    }
    if (std::abs(step) < tolerance) step = step > 0 ? tolerance : -tolerance;
    a = b, fa = fb;
    b += step;
    fb = f(b);
    if ((fb > 0 && fc > 0) || (fb < 0 && fc < 0)) c = a, fc = fa;
  }
  return b;
}

}  // namespace contactbench
