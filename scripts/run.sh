#!/usr/bin/env bash
# The main job: builds contactbench, generates the paper's surface A (Table 1) and prints its statistics.
# (The scenes issue turns this into the full comparison run.) The README's main command.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target contactbench
cli=build/release/app/contactbench
out=build/release/surface_A.txt
# Surface A: sigma = 0.5 um, H = 0.5, qr = 3.14e4 1/m, qs = Nyquist (4.02e6 1/m), 200 um, 256 x 256.
"$cli" generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 256 --seed 1 --out "$out"
"$cli" stats "$out"
