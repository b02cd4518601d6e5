#!/usr/bin/env bash
# The main job, the README's main command: builds contactbench and runs the seed paper's comparison on its
# default scene, surface A (Table 1): the plateau model (4- and 8-connectivity), GW-McCool, BGT, the BGT
# linear law and Persson against the boundary-element reference. Prints the comparison table; the curves,
# summary, table and plots land in runs/surface_A/ (untracked; scripts/record-paper.sh rewrites results/).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target contactbench
build/release/app/contactbench run scenes/paper/surface_A.toml --threads "$(nproc)" "$@"
