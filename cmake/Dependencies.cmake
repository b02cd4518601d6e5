# Every dependency comes from Debian's packages (scripts/install-deps.sh installs them); nothing is vendored.

find_package(Eigen3 3.4 REQUIRED NO_MODULE)   # libeigen3-dev
find_package(OpenMP REQUIRED COMPONENTS CXX)  # libgomp (g++)
find_package(CLI11 REQUIRED)                  # libcli11-dev
find_package(tomlplusplus 3 REQUIRED)        # libtomlplusplus-dev: scene files (its CMake package, compiled library)

# libzip-dev: .x3p archives (core, private). Through pkg-config: Debian's libzip CMake package refers to tools
# (zipcmp, ...) that libzip-dev does not install, so find_package(libzip) fails on a clean machine.
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBZIP REQUIRED IMPORTED_TARGET libzip)
find_package(pugixml REQUIRED CONFIG)        # libpugixml-dev: .x3p main.xml (core, private)

include(FFTWTargets)                          # libfftw3-dev: contactbench::fftw

if(CB_BUILD_TESTS)
  find_package(GTest REQUIRED)                # libgtest-dev
endif()
