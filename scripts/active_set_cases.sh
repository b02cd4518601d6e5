#!/usr/bin/env bash
# The 30 cold solves by which active_set's outer steps were tuned (docs/solvers_log.md, "Outer steps"): surface A
# refined to 256^2, 512^2 and 1024^2 and an H = 0.8 surface at 256^2 and 1024^2, periodic and non-periodic,
# about 1, 10 and 30 % contact, tolerance 1e-6 (TOL overrides). Prints each case's iterations and the total.
# Usage: scripts/active_set_cases.sh [CONTACTBENCH]   (default build/release/app/contactbench)
# The surfaces are made once into CASES_DIR (default /tmp/contactbench-cases). About 1 minute on two cores.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/release/app/contactbench}
dir=${CASES_DIR:-/tmp/contactbench-cases}
mkdir -p "$dir"
for n in 256 512 1024; do
  [[ -f $dir/A$n.x3p ]] || "$bin" generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 256 \
    --refine "$n" --out "$dir/A$n.x3p" >/dev/null
done
for n in 256 1024; do
  [[ -f $dir/H$n.x3p ]] || "$bin" generate --sigma 1e-6 --hurst 0.8 --qr 251327.4 --size 100e-6 --grid "$n" \
    --out "$dir/H$n.x3p" >/dev/null
done
# Loads P/(E* A0): surface A 0.000742 / 0.00742 / 0.0223 at every n (it has no roughness below the 256 grid's
# pixel); the H = 0.8 surface (pct/100) gbar/2 for pct = 1, 10, 30, gbar its rms gradient at that n (rounded).
declare -A loads=([A256]="0.000742 0.00742 0.0223" [A512]="0.000742 0.00742 0.0223"
  [A1024]="0.000742 0.00742 0.0223" [H256]="0.00335 0.0335 0.1" [H1024]="0.00466 0.0466 0.14")
total=0
for surface in A256 A512 A1024 H256 H1024; do
  for boundary in --periodic --non-periodic; do
    for load in ${loads[$surface]}; do
      iterations=$("$bin" bem "$dir/$surface.x3p" $boundary --loads "$load" --threads 2 --tolerance "${TOL:-1e-6}" \
        --solver active_set 2>/dev/null | grep '^bem,' | cut -d, -f10)
      echo "$surface $boundary $load $iterations"
      total=$((total + iterations))
    done
  done
done
echo "total $total"
