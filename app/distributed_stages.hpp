// The command line as several MPI ranks (mpirun -np K contactbench ..., docs/mpi.md): rank 0 runs the command
// as one process would (reads the inputs, runs the surface, moments and theories, writes every output), and
// the other ranks serve its distributed stages: the BEM solves and the sweep run on slabs of the grid across
// all ranks (contactbench::mpi). Rank 0 sends each stage's parameters and scatters the surface, or, for a
// generated surface, every rank generates its own slab and keeps it for the stages (no rank holds it whole
// unless a method reads the whole heights); the results come back to rank 0, so the outputs are the files a
// serial run writes. Stages with no distributed version
// are refused before any work, never run K times.
//
// Built only with CB_WITH_MPI (app/CMakeLists.txt); the program's serial path never calls it.
#pragma once

#include <functional>

#include "contactbench/app/stage_runner.hpp"

namespace contactbench {

// Starts MPI and FFTW-MPI; rank 0 runs `command` (the whole command line, its status the exit status) with
// the distributed runner (app/stage_runner.hpp) while the others serve its stages until it ends; then every
// rank stops. Returns this rank's exit status. A BEM stage with an option the distributed solver lacks (a
// hardness, single precision, the active_set solver, which is the default) is refused in preflight with the
// reason: the scene's solver is never replaced by another.
int run_as_mpi_ranks(int& argc, char**& argv, const std::function<int(const StageRunner&)>& command);

}  // namespace contactbench
