# The distributed build (docs/mpi.md): MPI (Debian's OpenMPI, libopenmpi-dev) and FFTW's MPI libraries
# (libfftw3-mpi-dev: libfftw3_mpi, and libfftw3f_mpi for single precision). CB_WITH_MPI is ON by default when
# both are found and may be turned OFF; asked ON without them, configuring fails and names the packages.
# Defines contactbench::fftw_mpi for the mpi/ library; the tests run under FindMPI's MPIEXEC_EXECUTABLE.
find_package(MPI COMPONENTS C CXX QUIET)
find_library(FFTW3_MPI_LIBRARY NAMES fftw3_mpi HINTS ${FFTW3_LIBRARY_DIRS})
find_library(FFTW3F_MPI_LIBRARY NAMES fftw3f_mpi HINTS ${FFTW3F_LIBRARY_DIRS})
find_path(FFTW3_MPI_INCLUDE_DIR NAMES fftw3-mpi.h HINTS ${FFTW3_INCLUDE_DIRS})

set(cb_mpi_available OFF)
if(MPI_CXX_FOUND AND MPIEXEC_EXECUTABLE AND FFTW3_MPI_LIBRARY AND FFTW3_MPI_INCLUDE_DIR)
  set(cb_mpi_available ON)
endif()
option(CB_WITH_MPI "Build the distributed (MPI + FFTW-MPI) library mpi/ and its tests" ${cb_mpi_available})

if(CB_WITH_MPI)
  if(NOT cb_mpi_available)
    message(FATAL_ERROR "CB_WITH_MPI=ON needs MPI and FFTW's MPI library (Debian: libopenmpi-dev "
                        "libfftw3-mpi-dev openmpi-bin); install them or configure with -DCB_WITH_MPI=OFF")
  endif()
  if(NOT TARGET contactbench::fftw_mpi)
    add_library(contactbench::fftw_mpi INTERFACE IMPORTED)
    target_include_directories(contactbench::fftw_mpi INTERFACE ${FFTW3_MPI_INCLUDE_DIR})
    target_link_libraries(contactbench::fftw_mpi INTERFACE ${FFTW3_MPI_LIBRARY} contactbench::fftw MPI::MPI_CXX)
    if(FFTW3F_MPI_LIBRARY)  # single precision: optional, nothing in mpi/ uses it yet
      target_link_libraries(contactbench::fftw_mpi INTERFACE ${FFTW3F_MPI_LIBRARY})
    endif()
  endif()
  message(STATUS "contactbench: distributed build on (MPI ${MPI_CXX_VERSION}, ${FFTW3_MPI_LIBRARY})")
else()
  message(STATUS "contactbench: distributed build off (CB_WITH_MPI=OFF, or MPI/FFTW-MPI not found)")
endif()
