// Brent's method (R. P. Brent, Algorithms for Minimization without Derivatives, 1973, ch. 4; the netlib
// zeroin): the bracketed root finder with which the theories solve for the separation that gives a load.
#pragma once

#include <functional>

#include "contactbench/core/types.hpp"

namespace contactbench {

// A root of f in the bracket [a, b], where fa = f(a) and fb = f(b) have opposite signs (or one is 0).
// Returns when |f| <= f_tolerance or the bracket is narrower than 4 eps |x| + x_tolerance.
Real find_root(const std::function<Real(Real)>& f, Real a, Real b, Real fa, Real fb, Real f_tolerance,
               Real x_tolerance);

}  // namespace contactbench
