// The command line as several MPI ranks (mpirun -np K contactbench ..., docs/mpi.md): rank 0 runs the command
// as one process would (reads the inputs, runs the surface, moments and theories, writes every output), and
// the other ranks serve its distributed stages: the BEM solves and the sweep run on slabs of the grid across
// all ranks (contactbench::mpi). Rank 0 sends each stage's parameters and scatters the surface; the results
// come back to rank 0, so the outputs are the files a serial run writes. Stages with no distributed version
// are refused before any work, never run K times.
//
// Built only with CB_WITH_MPI (app/CMakeLists.txt); the program's serial path never calls it.
#pragma once

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "contactbench/app/stages.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

// Starts MPI and FFTW-MPI; rank 0 runs `command` (the whole command line, its status the exit status) while
// the others serve its stages until it ends; then every rank stops. Returns this rank's exit status.
int run_as_mpi_ranks(int& argc, char**& argv, const std::function<int()>& command);

// Inside run_as_mpi_ranks on rank 0 with more than one rank: the stages below run distributed.
bool stages_are_distributed();
int distributed_rank_count();

// Why this BEM stage cannot run distributed (an option the distributed solver lacks), or empty.
std::string distributed_bem_refusal(const BemStage& stage);

// Rank 0: every load solved on slabs across the ranks, warm-started in increasing order, as solve_loads in
// app/stages.cpp does serially: per load the solver's scalars (fields not kept) and the statistics for each
// connectivity; with a non-empty `fields` prefix the pressure and gap gathered to rank 0 and written.
// `threads`: FFTW's threads on each rank. `warning`: the unconverged loads' notices. `bytes_per_rank`: the
// largest memory a rank held for the solve. Refuses (Error) what distributed_bem_refusal names.
struct DistributedLoads {
  std::vector<ContactSolution> solutions;
  std::map<int, std::vector<ContactStatistics>> statistics;
  std::size_t bytes_per_rank = 0;
};
DistributedLoads solve_loads_distributed(const BemStage& stage, const Surface& solved, Real estar,
                                         const std::vector<Real>& mean_pressures,
                                         const std::set<int>& connectivities, int threads,
                                         const std::string& fields,
                                         const std::function<void(const std::string&)>& warning);

// Rank 0: the sweep of `surface` on slabs across the ranks (mpi/distributed_sweep.hpp), equal to the serial
// sweep.
SweepCurve sweep_distributed(const Surface& surface, const SweepLevels& levels, const Topology& topology);

}  // namespace contactbench
