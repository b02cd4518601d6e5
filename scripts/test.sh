#!/usr/bin/env bash
# Builds contactbench and runs every test (unit, validation, end to end, install and consume, formatting,
# layering, fuzzing regressions). The README's test command; .ci/run calls it verbatim.
# Usage: scripts/test.sh [preset: release|debug|asan]
# With CB_CI=1 (set by .ci/run) it also fuzzes each parser for a few seconds (preset fuzz, scripts/fuzz.sh); with
# CB_CI_ASAN=1 as well (.ci/run sets it), it builds and runs the suite under AddressSanitizer + UBSan (preset
# asan; .ci/run from a fresh clone took 11 minutes on 2 quiet cores with both suites). `scripts/test.sh asan` runs it
# by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
scripts/install-deps.sh
cmake --preset "$preset"
cmake --build --preset "$preset" -j "$(nproc)"
ctest --preset "$preset" -j "$(nproc)"

if [[ "${CB_CI:-}" == "1" ]]; then
  scripts/test-wheel.sh  # a wheel built from the tree, installed into a fresh venv, python/tests run against it
  if [[ "${CB_CI_ASAN:-}" == "1" && "$preset" != "asan" ]]; then
    echo "test.sh: CI: the suite under AddressSanitizer + UBSan"
    cmake --preset asan
    cmake --build --preset asan -j "$(nproc)"
    ctest --preset asan -j "$(nproc)"
  fi
  echo "test.sh: CI: a short fuzz run of every parser"
  scripts/install-deps.sh fuzz
  scripts/fuzz.sh "${CB_FUZZ_SECONDS:-15}"
fi
