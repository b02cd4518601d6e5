# The distributed build (docs/mpi.md): MPI (Debian's OpenMPI, libopenmpi-dev) and FFTW's MPI libraries
# (libfftw3-mpi-dev), found by cmake/FFTWMpiTargets.cmake (contactbench::fftw_mpi). CB_WITH_MPI is ON by
# default when both are found and may be turned OFF; asked ON without them, configuring fails and names the
# packages. The tests run under FindMPI's MPIEXEC_EXECUTABLE, so it is needed too.
include(FFTWMpiTargets)

set(cb_mpi_available OFF)
if(CB_FFTW_MPI_FOUND AND MPIEXEC_EXECUTABLE)
  set(cb_mpi_available ON)
endif()
option(CB_WITH_MPI "Build the distributed (MPI + FFTW-MPI) library mpi/ and its tests" ${cb_mpi_available})

if(CB_WITH_MPI)
  if(NOT cb_mpi_available)
    message(FATAL_ERROR "CB_WITH_MPI=ON needs MPI and FFTW's MPI library (Debian: libopenmpi-dev "
                        "libfftw3-mpi-dev openmpi-bin); install them or configure with -DCB_WITH_MPI=OFF")
  endif()
  message(STATUS "contactbench: distributed build on (MPI ${MPI_CXX_VERSION}, ${FFTW3_MPI_LIBRARY})")
else()
  message(STATUS "contactbench: distributed build off (CB_WITH_MPI=OFF, or MPI/FFTW-MPI not found)")
endif()
