// boundary = "mirrored" of the BEM method (docs/solvers.md "Mirrored boundary"): a non-periodic record of
// n x m points is extended evenly to 2n x 2m points (the record, its left-right and up-down reflections and
// both), which has no step at the seams, and that extension is solved as a periodic surface. Every statistic
// is then taken on the original patch only. The extension is symmetric about the patch's edges, so the
// periodic solution is too, and the mean pressure on the patch is the load's.
#pragma once

#include <optional>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

// The grid of the even extension of a patch on `patch`: twice its points a side and twice its size, periodic.
Grid mirrored_grid(const Grid& patch);

// The even extension of `patch` (any periodicity) to twice its points a side and twice its size, periodic.
Surface mirrored_surface(const Surface& patch);

// The solution on the patch: the first nx x ny block of a solution on the mirrored grid (pressure, gap,
// plastic overlap cropped; contact points and plastic points, those at p >= hardness as the solvers count
// them, counted on it; mean pressure its mean). The solver's scalars (iterations, residual, converged,
// separation) stay the mirrored solve's.
ContactSolution patch_of(const ContactSolution& mirrored, Index nx, Index ny, std::optional<Real> hardness);

}  // namespace contactbench
