#!/usr/bin/env bash
# Runs the Google Benchmark harnesses (2 threads, medians of repetitions) and records them under
# results/bench/: <name>.json (Google Benchmark's output, with commit, date, threads and machine in its
# context) and <name>.md (tables with ratios to the references measured in the same run).
# Usage: scripts/bench.sh [labelling|sweep|bem ...]   (default: all). BENCH_FILTER=REGEX runs only the matching
# benchmarks (recorded in the files' command). Takes about 15 minutes for labelling and
# sweep, and as long again for bem.
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
cmake --build --preset release -j "$(nproc)" --target bench_labelling bench_sweep bench_bem

commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- core bem bench || commit="$commit+uncommitted"
# Google Benchmark takes one comma-separated key=value list: no commas inside the values.
machine="$(lscpu | sed -n 's/^Model name: *//p' | head -n 1 | tr ',' ' ') with $(nproc) cores"
mkdir -p results/bench
for name in "${@:-labelling sweep bem}"; do
  for bench in $name; do
    out=results/bench/$bench.json
    filter=${BENCH_FILTER:+--benchmark_filter=$BENCH_FILTER}
    build/release/bench/bench_$bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true $filter \
      --benchmark_out="$out.tmp" --benchmark_out_format=json \
      --benchmark_context="commit=$commit,machine=$machine,command=scripts/bench.sh $bench${BENCH_FILTER:+ with BENCH_FILTER set to $BENCH_FILTER}"
    mv "$out.tmp" "$out"
    python3 scripts/render_bench.py "$out" >"${out%.json}.md.tmp"
    mv "${out%.json}.md.tmp" "${out%.json}.md"
    echo "bench: wrote $out and ${out%.json}.md"
  done
done
