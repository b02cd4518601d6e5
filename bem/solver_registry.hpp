// The boundary-element solvers by name: what a scene's `solver = "..."` and the command line's `--solver`
// choose (docs/solvers.md). Every solver solves the same problem (bem/polonsky_keer.hpp) with the same
// options and the same stopping rules; they differ in how an iteration picks its search direction.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace contactbench {

enum class SolverKind {
  // Polonsky & Keer's constrained conjugate gradient (Wear 231, 1999): the direction from the gap itself.
  polonsky_keer,
  // The same with the gap filtered by |q| in Fourier space (bem/fourier_preconditioner.hpp) before it
  // becomes a direction: an iteration count that grows far more slowly with the grid.
  preconditioned_cg,
  // A primal-dual active-set (semismooth Newton) method: the linear problem on a guessed contact set solved
  // by the preconditioned CG, the set updated from p and the gap, from a nested coarse start
  // (bem/active_set.hpp).
  active_set,
};

// The solver a caller gets when it names none: the fastest that passes every validation (docs/solvers.md).
inline constexpr SolverKind kDefaultSolver = SolverKind::active_set;
// The default of a solve on several MPI ranks, where active_set has no distributed version (docs/mpi.md).
inline constexpr SolverKind kDefaultDistributedSolver = SolverKind::preconditioned_cg;

// The known names, in the order of SolverKind.
const std::vector<std::string>& solver_names();
// The name of a kind ("polonsky_keer", "preconditioned_cg").
std::string_view solver_name(SolverKind kind);
// The kind of a name; an unknown name throws Error naming it, `where` it came from, and every known name.
SolverKind solver_kind(std::string_view name, std::string_view where = "solver");

}  // namespace contactbench
