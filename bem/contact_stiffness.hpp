// The contact stiffness per unit area of a converged boundary-element state, K = -dP/dd, from its
// linearised response (docs/theory.md section 12.2): held on its elastic contact set C (0 < p, and p < H
// with a hardness: plastic points carry a fixed pressure), the surface moved towards the flat by a uniform
// delta needs the extra pressure x delta, where G x = 1 on C and x = 0 elsewhere; then K = mean(x) over the
// nominal area. G restricted to C is symmetric positive definite (the periodic operator's one null mode, the
// uniform field, is not supported on a proper subset of the grid), so conjugate gradients solve it.
//
// d is the flat's rigid approach (BemSolver's separation, with the sign of an approach). On a periodic grid
// the mean gap is d itself (the operator has no mean displacement), so K = -dP/du-bar too; on a
// non-periodic patch the mean gap moves with the far-field displacement as well, and K is -dP/dd only.
#pragma once

#include <optional>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

struct ContactStiffness {
  Real stiffness = 0;      // K [Pa/m]; +inf on a periodic grid in full contact; 0 without contact
  Index iterations = 0;    // of conjugate gradients
  Real residual = 0;       // |G x - 1| / |1| on C at the end
  bool converged = false;  // residual <= the tolerance asked
};

// `pressure` [Pa] on `grid` (its periodicity chooses the operator), modulus E* [Pa]; `hardness` [Pa] when
// the state was capped. Solves to the relative residual `tolerance` in at most `max_iterations`.
ContactStiffness contact_stiffness(const Grid& grid, Real modulus, const HeightMap& pressure,
                                   std::optional<Real> hardness = std::nullopt, int threads = 1,
                                   Real tolerance = 1e-10, Index max_iterations = 5000);

}  // namespace contactbench
