# contactbench::fftw_mpi: FFTW's distributed transforms (Debian's libfftw3-mpi-dev: libfftw3_mpi, and
# libfftw3f_mpi for single precision) with MPI (libopenmpi-dev). FFTW-MPI has neither a CMake package nor a
# pkg-config file on Debian 12, so it is found next to FFTW's main library (contactbench::fftw,
# cmake/FFTWTargets.cmake, included first). Included by cmake/Mpi.cmake and, for a package built with
# CB_WITH_MPI, by the installed config, so that a consumer of contactbench::mpi finds both the same way.
# Sets CB_FFTW_MPI_FOUND; defines the target only when everything is there.
find_package(MPI COMPONENTS C CXX QUIET)
find_library(FFTW3_MPI_LIBRARY NAMES fftw3_mpi HINTS ${FFTW3_LIBRARY_DIRS})
find_library(FFTW3F_MPI_LIBRARY NAMES fftw3f_mpi HINTS ${FFTW3F_LIBRARY_DIRS})
find_path(FFTW3_MPI_INCLUDE_DIR NAMES fftw3-mpi.h HINTS ${FFTW3_INCLUDE_DIRS})

set(CB_FFTW_MPI_FOUND OFF)
if(MPI_CXX_FOUND AND FFTW3_MPI_LIBRARY AND FFTW3_MPI_INCLUDE_DIR)
  set(CB_FFTW_MPI_FOUND ON)
  if(NOT TARGET contactbench::fftw_mpi)
    add_library(contactbench::fftw_mpi INTERFACE IMPORTED)
    target_include_directories(contactbench::fftw_mpi INTERFACE ${FFTW3_MPI_INCLUDE_DIR})
    target_link_libraries(contactbench::fftw_mpi INTERFACE ${FFTW3_MPI_LIBRARY} contactbench::fftw MPI::MPI_CXX)
    if(FFTW3F_MPI_LIBRARY)  # single precision: optional, nothing in mpi/ uses it yet
      target_link_libraries(contactbench::fftw_mpi INTERFACE ${FFTW3F_MPI_LIBRARY})
    endif()
  endif()
endif()
