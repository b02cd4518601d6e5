// The Maugis–Dugdale contact solved on the whole surface by one constrained conjugate gradient
// (docs/theory.md section 10.10, docs/solvers.md "Adhesion"): Polonsky and Keer's iteration (Wear 231, 1999)
// on the repulsive pressure p >= 0, with the attraction a(x) in {0, σ0} decided inside the iteration from the
// current gap, in the spirit of Rey, Anciaux and Molinari (Computational Mechanics 60, 69, 2017), who treat
// the cohesive zone inside the CG rather than around it. The fixed point (adhesive_solver.cpp) moves the
// zone's front once per converged contact solve; here it moves once per CG step. The result is a start:
// AdhesiveBemSolver then checks it with its own settling rule (a converged contact solve that changes no
// point's side), so the answer and its convergence flag are those of the fixed point.
#pragma once

#include <vector>

#include "contactbench/core/adhesion_law.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

class HalfSpace;

struct ConstrainedCgOutcome {
  Index iterations = 0;
  bool settled = false;  // the pressure changed by less than the tolerance in a step that moved no point
};

// Load control (load = true): the net mean traction mean(p - a) = value; separation control: the flat at
// `value`. `pressure` (p) and `attraction` (a) are the start and the result; heights are centred.
ConstrainedCgOutcome solve_dugdale_constrained_cg(HalfSpace& half_space, const HeightMap& heights,
                                                  const AdhesionLaw& law, bool load, Real value,
                                                  Real tolerance, Index max_iterations, HeightMap& pressure,
                                                  HeightMap& attraction);

}  // namespace contactbench
