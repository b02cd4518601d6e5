#include "contactbench/bem/love_kernel.hpp"

#include <cmath>
#include <numbers>

namespace contactbench {

namespace {

// v + sqrt(u^2 + v^2) without cancellation: for v < 0 it equals u^2 / (sqrt(u^2 + v^2) - v).
Real plus_hypot(Real v, Real u) {
  const Real h = std::hypot(u, v);
  return v >= 0 ? v + h : u * u / (h - v);
}

// f(u, v1, v2) = u ln[(v1 + sqrt(u^2 + v1^2)) / (v2 + sqrt(u^2 + v2^2))]; its limit at u = 0 is 0.
Real f(Real u, Real v1, Real v2) {
  if (u == 0) return 0;
  return u * (std::log(plus_hypot(v1, u)) - std::log(plus_hypot(v2, u)));
}

}  // namespace

Real love_displacement(Real x, Real y, Real a, Real b) {
  return (f(x + a, y + b, y - b) + f(y + b, x + a, x - a) + f(x - a, y - b, y + b) + f(y - b, x - a, x + a)) /
         std::numbers::pi;
}

}  // namespace contactbench
