#include "contactbench/mpi/environment.hpp"

#include <mpi.h>

#include <fftw3-mpi.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"

namespace contactbench::mpi {

namespace {
bool fftw_mpi_ready = false;
}

Environment::Environment(int& argc, char**& argv) {
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
