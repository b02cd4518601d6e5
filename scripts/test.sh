#!/usr/bin/env bash
# Builds contactbench and runs every test (unit, validation, end to end, install and consume, formatting,
# layering, fuzzing regressions, every shipped scene's preflight, the Python examples). The README's test
# command; .ci/run calls it verbatim.
# Usage: scripts/test.sh [preset: release|debug|asan]
# With CB_CI=1 (set by .ci/run) it also runs what only CI runs:
#   - CB_CI_ASAN=1: the suite under AddressSanitizer + UBSan with assertions on (preset asan: clang 14, -O1 -g1
#     without NDEBUG, so assert() and Eigen's bounds checks run, and _GLIBCXX_ASSERTIONS for the C++ library's),
#     the Python module's tests and the MPI tests included (see run_suite below for how). -O1 -g1 (ASan's own
#     advice: -O1; line tables only, enough for the reports' stacks) instead of -O2 -g: compiling three of the
#     heaviest files took 0.45-0.59 of the time (timed side by side, 2026-11-28), the build being CI's longest
#     stage (17.6 of 45 min at -O2 -g). The same build has the libFuzzer targets (CB_BUILD_FUZZERS), so the
#     fuzz run below builds nothing more: one clang build serves both. Timed from fresh clones with
#     `/usr/bin/time -v .ci/run`: before (a g++ build for the suite, a clang build for the fuzzers; bb46578) the
#     sanitizer build, suite and fuzz stage took 18.2 + 7.6 + 8.1 min of 56.5; after (b8a2e50, a slower day:
#     the release build 13.6 min against 11.0) 16.3 + 7.9 + 0.7 of 50.5; with unity builds (7eae334, the
#     builds 8.5, 4.5 and 9.8 min) 9.8 + 7.8 + 0.6 of 35.9;
#   - CB_CI_DEBUG=1 (off in .ci/run since the asan preset has the assertions): the whole suite of the debug
#     preset (no optimisation): 2-3 minutes of tests on 2 cores after a build of 5-6 minutes;
#   - a short fuzz run of each parser (scripts/fuzz.sh, from the asan preset's build; seeded, CB_FUZZ_SEED).
# `scripts/test.sh asan` or `scripts/test.sh debug` runs one of them by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
jobs=$(nproc)
# Two tests run at once on each pair of cores, each with OpenMP threads: idle threads that spin (OpenMP's default
# wait) take the cores the other test needs. Sleeping idle threads change no result, only the time.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-PASSIVE}
# Every stage says when it ends and how long the whole run has taken, so a slow CI run shows where its time went.
stage_done() { echo "test.sh: $1 done at $(date -u +%H:%M:%S), $((SECONDS / 60)) min $((SECONDS % 60)) s since the start"; }

# Builds a preset and runs its suite. With "again" (CI, after the release suite): without the benchmark
# harnesses, which no test runs, and without the source checks (formatting, layering), which do not depend on
# the build and have just passed.
run_suite() {
  local name=$1 again=${2:-} configure=() skip='^$'
  if [[ "$again" == again ]]; then
    configure=(-DCB_BUILD_BENCHMARKS=OFF)
    # The whole scenes and command lines on 3 ranks too: the release suite has just run them, and under the
    # sanitizers they were 3 of the asan suite's 15 minutes of test time (2 ranks run here, and the 3-rank
    # unit tests of the uneven slabs, mpi_ranks_3). And the two longest numerical claims, which the release
    # suite has just checked and whose code other tests run under the sanitizers: the declared load path's
    # cost against cold solves (86 s under ASan; LoadPath.EveryStartGivesTheColdAnswers runs every start) and
    # the pull-off's location (45 s; the other AdhesivePath tests run the path).
    skip='^(format_check|layer_check|mpi_scenes_ranks_3|mpi_cli_ranks_3'
    skip+='|LoadPathDeclared.TheDefaultSolversCurveCostsNoMoreThanColdSolves'
    skip+='|AdhesivePath.LocatesThePullOffBetweenItsSamples)$'
  fi
  [[ "$name" == asan ]] && scripts/install-deps.sh asan  # clang 14, its sanitizer runtimes and libomp
  cmake --preset "$name" "${configure[@]}"
  cmake --build --preset "$name" -j "$jobs"
  stage_done "build of preset $name"
  case "$name" in
    asan)
      # The Python module under AddressSanitizer: the interpreter is not instrumented, so the ASan runtime
      # must be loaded first (LD_PRELOAD, else "ASan runtime does not come first"; clang's shared runtime,
      # which every target of the preset links, CMakeLists.txt), and with it the C++ runtime (else ASan's
      # interceptor of __cxa_throw finds no real one, as python3 does not link libstdc++, and the first C++
      # exception aborts: "CHECK failed: asan_interceptors.cpp"). Leak detection is off for these tests only:
      # CPython keeps interned objects and module state to the end by design, which LeakSanitizer reports as
      # leaks (every other test keeps leak detection on).
      ctest --preset asan -j "$jobs" -E "^python_|$skip"
      if ctest --preset asan -N -R '^python_' | grep -q 'Total Tests: [1-9]'; then
        local compiler preload
        compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' build/asan/CMakeCache.txt)
        if "$compiler" --version | grep -q clang; then
          preload="$("$compiler" -print-runtime-dir)/libclang_rt.asan-x86_64.so"
        else  # g++ (a by-hand -DCMAKE_CXX_COMPILER=g++ configure of the preset)
          preload=$("$compiler" -print-file-name=libasan.so)
        fi
        preload="$preload $("$compiler" -print-file-name=libstdc++.so)"
        echo "test.sh: the Python tests under AddressSanitizer (LD_PRELOAD=$preload, detect_leaks=0)"
        LD_PRELOAD="$preload" ASAN_OPTIONS=detect_leaks=0 ctest --preset asan -j "$jobs" -R '^python_'
      fi
      ;;
    *)
      ctest --preset "$name" -j "$jobs" -E "$skip"
      ;;
  esac
  stage_done "suite of preset $name"
}

scripts/install-deps.sh
run_suite "$preset"

if [[ "${CB_CI:-}" == "1" ]]; then
  scripts/test-wheel.sh  # a wheel built from the tree, installed into a fresh venv, python/tests run against it
  stage_done "the wheel's suite"
  if [[ "${CB_CI_ASAN:-}" == "1" && "$preset" != "asan" ]]; then
    echo "test.sh: CI: the suite under AddressSanitizer + UBSan"
    run_suite asan again
  fi
  if [[ "${CB_CI_DEBUG:-}" == "1" && "$preset" != "debug" ]]; then
    echo "test.sh: CI: the debug suite (assertions on)"
    run_suite debug again
  fi
  # From the asan preset's build (built above when CB_CI_ASAN=1; else fuzz.sh installs clang and builds its
  # fuzz targets alone).
  echo "test.sh: CI: a short fuzz run of every parser"
  scripts/fuzz.sh "${CB_FUZZ_SECONDS:-15}"
  stage_done "fuzz run"
fi
