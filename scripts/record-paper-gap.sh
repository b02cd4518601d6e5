#!/usr/bin/env bash
# Rewrites results/<scene>_gap/ for surface_A, surface_B and measured: the paper's scenes with the mean gap and
# the contact stiffness compared besides the area (scenes/paper/<scene>_gap.toml, compare = ["area",
# "mean_gap", "stiffness"]; docs/theory.md section 12). The README's gap and stiffness numbers come from these
# table.md files.
# Usage: scripts/record-paper-gap.sh [threads, default 2]
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-2}
cmake --preset release >/dev/null
cmake --build --preset release -j 2 --target contactbench
for scene in surface_A surface_B measured; do
  build/release/app/contactbench run "scenes/paper/${scene}_gap.toml" --threads "$threads" --out "results/${scene}_gap" --quiet
  echo "record-paper-gap: results/${scene}_gap/ written"
done
