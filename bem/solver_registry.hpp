// The boundary-element solvers by name: what a scene's `solver = "..."` and the command line's `--solver`
// choose (docs/solvers.md). Every solver solves the same problem (bem/bem_solver.hpp) with the same
// options and the same stopping rules; they differ in how an iteration picks its search direction. Each is a
// class behind one interface (bem/solvers/contact_solver.hpp) that registers itself here: its name, what it
// does, what it supports natively, and how to make it.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "contactbench/core/surface.hpp"

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

class ContactSolver;  // bem/solvers/contact_solver.hpp

// Where a load-controlled solve starts after a previous load (load stepping; docs/solvers.md "Starts"):
//   scaled, the last solution scaled to the new load;
//   extrapolated, the linear extrapolation of the last two solutions in the load (clipped at 0, then
//     scaled), the last one scaled when there is only one;
//   cold, as if there were no previous load (each solver's own cold start: active_set's nested coarse
//     start, the uniform pressure for the others);
//   solver, the start the solver declares for the grid (SolverEntry::load_path): the one measured
//     cheapest on the benchmark's load curves (bench/bench_load_path.cpp). Only BemSolverOptions::load_path
//     takes it.
// The order is that of the scene key's choices (app/methods/bem_settings.cpp).
enum class LoadPathStart { scaled, extrapolated, cold, solver };

// One solver as it registers itself.
struct SolverEntry {
  SolverKind kind = SolverKind::polonsky_keer;
  std::string_view name;         // as scenes and --solver spell it
  std::string_view description;  // one line
  // What it does itself, without help from BemSolver: separation control with its own iteration (else it
  // iterates as polonsky_keer there), a hardness under load control in one solve (else BemSolver searches
  // the flat's height, bem/solvers/hardness_search.hpp), and single precision.
  bool separation_control = false;
  bool hardness = false;
  bool single_precision = false;
  // How it starts a load after a previous one on a grid when the caller leaves it to the solver
  // (BemSolverOptions::load_path = solver), with the pressure capped at a hardness or not: scaled,
  // extrapolated or cold, chosen by measurement (docs/solvers.md "Starts", bench/bench_load_path.cpp,
  // bench/bench_bem_solvers.cpp plastic rows). Empty: scaled.
  std::function<LoadPathStart(const Grid& grid, bool capped)> load_path;
  // Makes the solver for a centred surface, E* [Pa], threads, in float when single_precision.
  std::function<std::unique_ptr<ContactSolver>(const Surface& centred, Real modulus, int threads,
                                               bool single_precision)>
      make;
};

// Every solver, in the order of SolverKind.
const std::vector<SolverEntry>& solver_registry();
// The entry of a kind.
const SolverEntry& solver_entry(SolverKind kind);

// The known names, in the order of SolverKind.
const std::vector<std::string>& solver_names();
// The name of a kind ("polonsky_keer", "preconditioned_cg").
std::string_view solver_name(SolverKind kind);
// The scene key's spelling of a start ("scaled", "extrapolated", "cold", "solver").
std::string_view load_path_start_name(LoadPathStart start);
// The kind of a name; an unknown name throws Error naming it, `where` it came from, and every known name.
SolverKind solver_kind(std::string_view name, std::string_view where = "solver");

}  // namespace contactbench
