// A hardness under load control for the solvers that do not meet it in one solve (SolverEntry::hardness
// false: polonsky_keer, preconditioned_cg). Rescaling the pressure to the load, PK's way of imposing it,
// does not commute with the cap, so the cap is met the way a rigid-body approach is: the capped problem is
// solved for the flat's height d (separation control, where the cap is a plain projection onto [0, H]),
// and d is searched until the mean pressure is the load (docs/solvers.md "Hardness"). Internal to the
// solvers (bem/solvers/).
#pragma once

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/solvers/contact_solver.hpp"

namespace contactbench {

// What a search leaves for the next load's: the load it met, the flat's height that met it, and the local
// stiffness k = -dP/dd of the capped load there (the secant of its last two trials). The next search starts
// at d - (P_next - P)/k and steps by its excess over k (a Newton step on the capped curve) instead of from
// the elastic solution; stiffness 0: nothing to start from.
struct FlatHeightMemory {
  Real mean_pressure = 0;
  Real separation = 0;
  Real stiffness = 0;  // [Pa/m]
};

// The capped solution under load control: the flat's height d bracketed from the elastic solution just
// computed (its d carries less than the load once capped, and lower flats carry more: the load is a
// continuous, non-increasing function of d), then regula falsi with the Illinois modification, each trial a
// capped solve under separation control warm-started from the last, until the mean pressure is the load to
// the tolerance. Leaves the solver at the trial that met the tolerance, with the elastic pressures then
// rescaled to the load exactly. Returns the trials' iterations, summed. With from_memory, the solver holds
// the last search's state (no elastic solve was made for this load) and the search starts at the height
// `memory` predicts; either way `memory` is then this search's.
SolveOutcome search_flat_height(ContactSolver& solver, const HeightMap& heights,
                                const BemSolverOptions& options, Real mean_pressure, FlatHeightMemory& memory,
                                bool from_memory);

}  // namespace contactbench
