#include "contactbench/mpi/environment.hpp"

#include <malloc.h>
#include <mpi.h>

#include <limits>

#include <fftw3-mpi.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"

namespace contactbench::mpi {

namespace {
bool fftw_mpi_ready = false;
}

Environment::Environment(int& argc, char**& argv) {
  // FFTW-MPI's transposes allocate a scratch buffer of the slab's size at every transform and free it after.
  // glibc serves blocks above 32 MiB by a fresh mmap and unmaps them at free, so every transform of a large
  // slab faulted its buffer in again, page by page, zeroed by the kernel: at 4096^2 on 2 ranks 2.0 million
  // minor faults and 9 s of system time a 66 s solve. Kept in the heap (no mmap, no trimming of its top), the
  // buffer is reused: 0.18 million faults, 2.6 s, the solve 55 s (docs/mpi.md). The peak is unchanged; the
  // process keeps it until it exits, which a solve's process does soon after.
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  // lock_fftw_planner() initialises FFTW's threads, which must come before fftw_mpi_init.
  auto lock = lock_fftw_planner();
  fftw_mpi_init();
  fftw_mpi_ready = true;
}

// No fftw_mpi_cleanup: it would free every FFTW plan, including those core keeps cached per thread
// (core/fft.hpp), which are destroyed later, at thread exit.
Environment::~Environment() {
  fftw_mpi_ready = false;
  MPI_Finalize();
}

void require_fftw_mpi() {
  if (!fftw_mpi_ready)
    throw Error("mpi: the distributed classes need a contactbench::mpi::Environment alive (created in main)");
}

}  // namespace contactbench::mpi
