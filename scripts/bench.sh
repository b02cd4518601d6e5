#!/usr/bin/env bash
# Runs the Google Benchmark harnesses (2 threads, medians of repetitions) and records them under
# results/bench/: <name>.json (Google Benchmark's output, with commit, date, threads and machine in its
# context) and <name>.md (tables with ratios to the references measured in the same run).
# Usage: scripts/bench.sh [labelling|sweep|bem|bem_solvers|bem_adhesion|fill|formats_read|command|load_path|contact_stiffness ...]
#   (default: labelling sweep bem).
# BENCH_FILTER=REGEX runs only the matching benchmarks (recorded in the files' command); BENCH_REPETITIONS=N
# repeats each N times instead of 3 (recorded too: for iteration counts, which do not vary); BENCH_APPEND=1 adds
# them to the recorded JSON instead of replacing it (a long run made in parts); BENCH_RECORD=NAME records
# under results/bench/NAME.{json,md} instead of the harness's name (one family of a harness on its own). bem_solvers compares the BEM
# solvers at equal accuracy (bench/bench_bem_solvers.cpp); its full matrix takes hours on two cores, so it is
# run in parts with BENCH_FILTER (results/bench/bem_solvers.md records which). Takes about 15 minutes for
# labelling and sweep, and as long again for bem; command (the whole bem command beside its solve) a few
# minutes; load_path (each solver's load curves warm against cold, bench/bench_load_path.cpp) about an hour
# on two cores (BENCH_FILTER for parts).
# contact_stiffness (the stiffness solves of a paper scene, before and after issue 36) about one minute.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# OpenCV is the optional reference labeller; the benchmarks run without it, with fewer columns.
if ! dpkg-query -W -f='${Status}' libopencv-dev 2>/dev/null | grep -q "install ok installed"; then
  if [[ $(id -u) -eq 0 ]]; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends libopencv-dev >/dev/null ||
      echo "bench: libopencv-dev could not be installed; OpenCV columns will be missing" >&2
  fi
fi
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target bench_labelling bench_sweep bench_bem bench_bem_solvers \
  bench_bem_adhesion bench_fill bench_command bench_load_path \
  bench_contact_stiffness
# formats_read: reading a 4096^2 file of each binary format (bench/bench_formats_read.cpp), about 5 minutes.
cmake --build --preset release -j "$(nproc)" --target bench_formats_read

commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- core bem bench || commit="$commit+uncommitted"
# Google Benchmark takes one comma-separated key=value list: no commas inside the values.
machine="$(lscpu | sed -n 's/^Model name: *//p' | head -n 1 | tr ',' ' ') with $(nproc) cores"
mkdir -p results/bench
for name in "${@:-labelling sweep bem}"; do
  for bench in $name; do
    out=results/bench/${BENCH_RECORD:-$bench}.json
    filter=${BENCH_FILTER:+--benchmark_filter=$BENCH_FILTER}
    build/release/bench/bench_$bench --benchmark_repetitions="${BENCH_REPETITIONS:-3}" \
      --benchmark_report_aggregates_only=true $filter --benchmark_out="$out.tmp" --benchmark_out_format=json \
      --benchmark_context="commit=$commit,machine=$machine,command=scripts/bench.sh $bench${BENCH_RECORD:+ with BENCH_RECORD set to $BENCH_RECORD}${BENCH_REPETITIONS:+ with BENCH_REPETITIONS set to $BENCH_REPETITIONS}${BENCH_FILTER:+ with BENCH_FILTER set to $BENCH_FILTER}"
    if [[ -n ${BENCH_APPEND:-} && -f $out ]]; then
      # Adds this run's benchmarks to the recorded ones (replacing any of the same name); the context keeps
      # every run's command, commit and date, one entry each, so that render_bench.py can list the runs.
      python3 - "$out" "$out.tmp" <<'PY'
import json, sys
old, new = (json.load(open(p)) for p in sys.argv[1:3])
names = {b["name"] for b in new["benchmarks"]}
new["benchmarks"] = [b for b in old["benchmarks"] if b["name"] not in names] + new["benchmarks"]
for key in ("command", "commit", "date"):
    new["context"][key] = f'{old["context"].get(key)}; then {new["context"].get(key)}'
json.dump(new, open(sys.argv[2], "w"), indent=2)
PY
    fi
    mv "$out.tmp" "$out"
    python3 scripts/render_bench.py "$out" >"${out%.json}.md.tmp"
    mv "${out%.json}.md.tmp" "${out%.json}.md"
    echo "bench: wrote $out and ${out%.json}.md"
  done
done
