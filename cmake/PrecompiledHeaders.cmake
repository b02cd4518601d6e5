# Precompiled headers: the third-party headers nearly every file includes are parsed once a target instead of
# once a file. core/types.hpp brings Eigen/Core into almost every translation unit (2 s of parsing each), every
# test GoogleTest (2.2 s), the Python bindings pybind11 (3.7 s) (g++ 12 -fsyntax-only of the header alone,
# 2026-11-28). CLI11 and toml++ stay out: their cost in a command file is code generation, not parsing, and a
# precompiled header with them made app/'s small files 2.7x slower to compile (CPU seconds, same machine).
#
# Only headers from outside the project go in: a project header in a precompiled header would hide a missing
# #include (the install_and_consume test compiles the installed headers without these). Each library makes its
# own; the tests share one (same flags and definitions). The benchmarks have none (CI does not build them twice).
#
# Off by default under ccache (CMAKE_CXX_COMPILER_LAUNCHER): ccache does not cache a compile that uses a
# precompiled header unless told to be sloppy about it, and a cached rebuild is faster than either.
set(_cb_pch_default ON)
if(CMAKE_CXX_COMPILER_LAUNCHER MATCHES "ccache")
  set(_cb_pch_default OFF)
endif()
option(CB_PRECOMPILE_HEADERS "Precompile the third-party headers (Eigen, the standard library, GoogleTest, \
pybind11) of each target" ${_cb_pch_default})

set(CB_PCH_STANDARD_HEADERS
    <algorithm> <array> <cmath> <complex> <cstddef> <cstdint> <filesystem> <functional> <limits> <memory>
    <optional> <span> <sstream> <string> <string_view> <utility> <vector>)

# cb_precompile_headers(<target> [<header>...]): the standard headers above, Eigen/Core and the given ones.
function(cb_precompile_headers target)
  if(CB_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE ${CB_PCH_STANDARD_HEADERS} <Eigen/Core> ${ARGN})
  endif()
endfunction()

# cb_reuse_precompiled_headers(<target> <from>): <target> uses <from>'s precompiled header (same flags).
function(cb_reuse_precompiled_headers target from)
  if(CB_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()
