# Every dependency comes from Debian's packages (scripts/install-deps.sh installs them); nothing is vendored.

find_package(Eigen3 3.4 REQUIRED NO_MODULE)   # libeigen3-dev
find_package(OpenMP REQUIRED COMPONENTS CXX)  # libgomp (g++)
find_package(CLI11 REQUIRED)                  # libcli11-dev
find_package(tomlplusplus 3 REQUIRED)        # libtomlplusplus-dev: scene files (its CMake package, compiled library)

include(FFTWTargets)                          # libfftw3-dev: contactbench::fftw

if(CB_BUILD_TESTS)
  find_package(GTest REQUIRED)                # libgtest-dev
endif()
