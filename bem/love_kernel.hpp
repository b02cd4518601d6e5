// The normal surface displacement of an elastic half-space under a uniform pressure on a rectangle
// (A. E. H. Love, Phil. Trans. R. Soc. A 228, 1929; docs/theory.md section 6): the kernel of the non-periodic
// boundary-element operator, one pixel of pressure at a time.
#pragma once

#include "contactbench/core/types.hpp"

namespace contactbench {

// Displacement at (x, y) [m] for unit pressure over the rectangle |x| <= a, |y| <= b and E* = 1:
//   u = (1/pi) [f(x+a, y+b, y-b) + f(y+b, x+a, x-a) + f(x-a, y-b, y+b) + f(y-b, x-a, x+a)],
//   f(u, v1, v2) = u ln[(v1 + sqrt(u^2 + v1^2)) / (v2 + sqrt(u^2 + v2^2))].
// Multiply by p/E* for a pressure p. Check: centre of a square of side s gives (4 ln(1 + sqrt2)/pi) s.
Real love_displacement(Real x, Real y, Real a, Real b);

}  // namespace contactbench
