// Levelling a line scan (docs/formats.md "line scans"): the least-squares polynomial of degree 0, 1 or 2 in x
// removed from a profile h(x) sampled at increasing, possibly uneven x. A stylus trace is rarely level: its
// tilt would otherwise enter the rms slope m2 that the analytic theories read.
#pragma once

#include <span>
#include <vector>

#include "contactbench/core/formats/surface_repair.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// The heights less the fitted polynomial: none leaves them, mean removes the mean, plane the line a + b x,
// quadratic a + b x + c x^2. Each sample weighs the length of x it stands for (half its two segments), so
// that uneven sampling does not weigh the densely sampled parts more. Throws Error for fewer points than the
// polynomial has coefficients, or x not strictly increasing.
std::vector<Real> level_profile(std::span<const Real> x, std::span<const Real> h, Levelling levelling);

}  // namespace contactbench
