#include "contactbench/theories/brent_root.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/number_text.hpp"

namespace contactbench {

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
