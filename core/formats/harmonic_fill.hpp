// The harmonic fill of a measured topography's invalid points (docs/formats.md "invalid points"): the
// discrete Laplace equation on the invalid points, the valid ones fixed, solved by a conjugate gradient
// preconditioned with an aggregation multigrid cycle, so the cost grows like the number of points
// (docs/formats.md "The harmonic fill's solver").
#pragma once

#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

// What the fill did: the unknowns, the multigrid levels, the conjugate-gradient iterations and the relative
// residual reached.
struct HarmonicFillReport {
  Index unknowns = 0;
  Index levels = 0;
  Index iterations = 0;
  Real relative_residual = 0;
};

// The relative residual ||b - A h|| / ||b|| the fill stops at: far below the heights' own round-off to the
// eye, and the direct solve it replaced reached the same (docs/formats.md).
inline constexpr Real kHarmonicFillTolerance = 1e-12;

// Replaces every NaN of `values` (ny x nx, row-major) by the harmonic interpolation of the valid values: each
// filled height is the mean of its in-grid neighbours. At least one value must be valid (every connected
// patch of invalid points then touches a valid one and the system is positive definite). Throws Error when
// the iteration does not reach kHarmonicFillTolerance (never returns an unconverged fill).
HarmonicFillReport fill_harmonic(std::vector<Real>& values, Index nx, Index ny);

}  // namespace contactbench
