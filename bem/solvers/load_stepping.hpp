// Where a load-controlled solve starts (BemSolverOptions::load_path and coarse_start; docs/solvers.md):
// after a previous load, as the solver declares or the options force (load_path_start below): warm, from
// its solution scaled to the new load or from the extrapolation of the last two (PressureState::begin_load,
// load_stepping.cpp), or cold; cold, optionally from the solution of the surface averaged over 2 x 2 blocks
// (coarse_start below). Internal to the solvers (bem/solvers/).
#pragma once

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/solvers/contact_solver.hpp"

namespace contactbench {

// The start a load after a previous one takes on `grid`: options.load_path, or when that is `solver` the
// start the solver declares for the grid (SolverEntry::load_path). Never `solver`.
LoadPathStart load_path_start(const BemSolverOptions& options, const Grid& grid);

// Solves the surface averaged over 2 x 2 blocks (its mean kept, so the load is the same) loosely, itself
// from a coarser start down to 64 points a side, and starts `solver` from its pressure injected. Elastic: a
// hardness is met afterwards by the fine solve. Returns the coarse levels' iterations (0, and no start,
// when the grid is odd or too small).
Index coarse_start(ContactSolver& solver, const Surface& surface, Real modulus,
                   const BemSolverOptions& options, int threads, Real mean_pressure);

}  // namespace contactbench
