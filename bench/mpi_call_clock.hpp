// The time a process spends inside MPI calls, measured through MPI's profiling interface: mpi_call_clock.cpp
// defines the MPI functions the distributed solve and FFTW-MPI call, each timing the real one (its PMPI_
// name). So the global transposes are timed inside a solve, not apart: FFTW-MPI's transposes and the padded
// convolutions' row exchanges are all-to-all exchanges (MPI_Alltoall, MPI_Alltoallv, MPI_Alltoallw, or
// MPI_Sendrecv when FFTW picks its pairwise transpose), and so are the barriers of the slab engine's exchange
// in shared memory (mpi/exchange_storage.hpp), where the ranks wait for each other instead; the solver's sums
// are reductions. A call's time includes its wait for the slowest rank, and the local reordering FFTW does
// around an exchange is not in it. Linked into bench_mpi only (the product never times its MPI calls).
#pragma once

namespace contactbench::bench {

struct MpiCallTimes {
  double exchange_seconds = 0;   // inside MPI_Alltoall(v, w), MPI_Sendrecv, MPI_Barrier
  double reduction_seconds = 0;  // inside MPI_Allreduce, MPI_Allgather, MPI_Bcast
};

// This process's times since the last reset.
MpiCallTimes mpi_call_times();
void reset_mpi_call_times();

}  // namespace contactbench::bench
