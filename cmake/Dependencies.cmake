# Every dependency comes from Debian's packages (scripts/install-deps.sh installs them); nothing is vendored.

find_package(Eigen3 3.4 REQUIRED NO_MODULE)   # libeigen3-dev
find_package(OpenMP REQUIRED COMPONENTS CXX)  # libgomp (g++)
find_package(CLI11 REQUIRED)                  # libcli11-dev
find_package(tomlplusplus 3 REQUIRED)        # libtomlplusplus-dev: scene files (its CMake package, compiled library)

# FFTW (libfftw3-dev) ships a pkg-config file but no CMake package on Debian 12;
# its OpenMP library has neither, so it is found next to the main library.
find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
find_library(FFTW3_OMP_LIBRARY NAMES fftw3_omp HINTS ${FFTW3_LIBRARY_DIRS} REQUIRED)
# Single precision (fftwf_*, the BEM's float option): same package, found the same way.
pkg_check_modules(FFTW3F REQUIRED IMPORTED_TARGET fftw3f)
find_library(FFTW3F_OMP_LIBRARY NAMES fftw3f_omp HINTS ${FFTW3F_LIBRARY_DIRS} REQUIRED)
add_library(contactbench_fftw INTERFACE)
target_link_libraries(contactbench_fftw INTERFACE ${FFTW3_OMP_LIBRARY} ${FFTW3F_OMP_LIBRARY} PkgConfig::FFTW3
                      PkgConfig::FFTW3F OpenMP::OpenMP_CXX)

if(CB_BUILD_TESTS)
  find_package(GTest REQUIRED)                # libgtest-dev
endif()
