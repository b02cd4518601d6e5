// Starting and stopping the distributed runtime: MPI, then FFTW-MPI (which needs MPI running and, for
// threaded transforms, FFTW's threads set up first).
#pragma once

namespace contactbench::mpi {

// Owns MPI and FFTW-MPI for a program's lifetime (one per process, in main): MPI_Init_thread (funneled: only
// the main thread calls MPI), then fftw_mpi_init; on destruction MPI_Finalize. It also keeps large freed
// blocks in the process's heap (docs/mpi.md "Scratch buffers of the transposes").
class Environment {
 public:
  Environment(int& argc, char**& argv);
  ~Environment();
  Environment(const Environment&) = delete;
  Environment& operator=(const Environment&) = delete;
};

// Throws Error unless an Environment is alive (the distributed classes call it before touching FFTW-MPI).
void require_fftw_mpi();

}  // namespace contactbench::mpi
