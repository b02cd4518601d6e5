# contactbench::fftw: FFTW's double and single precision libraries with their OpenMP threading libraries
# (Debian's libfftw3-dev). FFTW ships a pkg-config file but no CMake package on Debian 12 and its OpenMP
# libraries have neither, so they are found next to the main libraries. Included by the project and by the
# installed package's config (contactbenchConfig.cmake), so that a consumer finds FFTW the same way.
if(NOT TARGET contactbench::fftw)
  find_package(PkgConfig REQUIRED)
  find_package(OpenMP REQUIRED COMPONENTS CXX)
  pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
  find_library(FFTW3_OMP_LIBRARY NAMES fftw3_omp HINTS ${FFTW3_LIBRARY_DIRS} REQUIRED)
  # Single precision (fftwf_*, the BEM's float option): same package, found the same way.
  pkg_check_modules(FFTW3F REQUIRED IMPORTED_TARGET fftw3f)
  find_library(FFTW3F_OMP_LIBRARY NAMES fftw3f_omp HINTS ${FFTW3F_LIBRARY_DIRS} REQUIRED)
  add_library(contactbench::fftw INTERFACE IMPORTED)
  target_link_libraries(contactbench::fftw INTERFACE ${FFTW3_OMP_LIBRARY} ${FFTW3F_OMP_LIBRARY} PkgConfig::FFTW3
                        PkgConfig::FFTW3F OpenMP::OpenMP_CXX)
endif()
