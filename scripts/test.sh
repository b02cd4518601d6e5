#!/usr/bin/env bash
# Builds contactbench and runs every test (unit, validation, end to end, formatting, layering).
# The README's test command; .ci/run calls it verbatim. Usage: scripts/test.sh [preset: release|debug|asan]
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
scripts/install-deps.sh
cmake --preset "$preset"
cmake --build --preset "$preset" -j "$(nproc)"
ctest --preset "$preset" -j "$(nproc)"
