// Whether the program was started as several ranks of an MPI job (mpirun / mpiexec -np K), read from what the
// launchers put in each process's environment, before MPI is started: `run`, `bem` and `sweep` then run as
// ranks (app/distributed_stages.hpp), other commands refuse rather than run K copies that would each do the
// whole work and write the same files (docs/mpi.md).
#pragma once

namespace contactbench {

struct MpiLaunch {
  int ranks = 1;  // 1 when not started by an MPI launcher
  int rank = 0;
};

// From OMPI_COMM_WORLD_SIZE / OMPI_COMM_WORLD_RANK (Open MPI) or PMI_SIZE / PMI_RANK (MPICH and others).
MpiLaunch mpi_launch();

}  // namespace contactbench
