# Unity builds: CMake compiles each target's sources in batches of eight files to a translation unit
# (CMAKE_UNITY_BUILD), so what the files of a target share (the project's headers, the templates of Eigen,
# GoogleTest and the standard library they instantiate, the inline functions they compile) is parsed and
# compiled once a batch instead of once a file. Beside the precompiled headers (cmake/PrecompiledHeaders.cmake)
# it took a clean release build from 777 s to 468 s of wall time, 1381 s to 836 s of CPU (`/usr/bin/time
# cmake --build <folder> -j2`, both from clean folders one after the other on this project's 2-core machine,
# 2026-11-29: 3e60118 against the commit that brought this file).
#
# On by default, off under ccache (CMAKE_CXX_COMPILER_LAUNCHER), as the precompiled headers: ccache caches a
# file on its own, and a change to one file would recompile its whole batch.
#
# The files of a batch share one translation unit, so two files of one target must not define the same name
# at namespace scope, even in an anonymous namespace: a constant or helper several files need lives once in a
# header (pi in core/types.hpp, the tests' constants in tests/test_constants.hpp). A build under ccache does
# not see such a clash; a clean build without it (CI's, the README's first command) does, and fails.
set(_cb_unity_default ON)
if(CMAKE_CXX_COMPILER_LAUNCHER MATCHES "ccache")
  set(_cb_unity_default OFF)
endif()
option(CB_UNITY_BUILD "Compile each target's sources in batches (CMAKE_UNITY_BUILD)" ${_cb_unity_default})
if(CB_UNITY_BUILD)
  set(CMAKE_UNITY_BUILD ON)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE 8)
endif()
