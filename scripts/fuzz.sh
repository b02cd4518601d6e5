#!/usr/bin/env bash
# Fuzzes every parser of untrusted input with libFuzzer (the fuzz targets of the `asan` preset's build: clang,
# ASan + UBSan + LeakSanitizer, assertions on; only they are built here when that build does not exist yet):
# the topography readers (fuzz_topography) and the scene parser (fuzz_scene), each for SECONDS, seeded with the
# project's own files. Any crashing, leaking or hanging input is copied to fuzz/regressions/<target>/, where the
# test suite replays it (tests/test_fuzz_regressions.cpp). Writes results/fuzz.md (executions, crashes, leaks)
# when asked to record.
# Usage: scripts/fuzz.sh [SECONDS per target, default 60] [--record]
# libFuzzer's random seed is fixed (CB_FUZZ_SEED, default 41; printed), so a repeated run on the same commit
# makes the same mutations in the same order (how many it gets through in SECONDS depends on the machine) and
# finds a problem again; set CB_FUZZ_SEED to explore other paths (0: libFuzzer picks one, printed in the log).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
record=${2:-}
seed=${CB_FUZZ_SEED:-41}
echo "fuzz: libFuzzer seed $seed (CB_FUZZ_SEED overrides it)"
scripts/install-deps.sh asan
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$(nproc)" --target fuzz_topography fuzz_scene >/dev/null

work=build/asan/fuzz-runs
rm -rf "$work"
mkdir -p "$work"
# Seed corpora: small real inputs (libFuzzer mutates them; large files only slow each execution down).
mkdir -p "$work/corpus_topography" "$work/corpus_scene"
for file in data/measured/*.txt; do head -c 4096 "$file" >"$work/corpus_topography/$(basename "$file")"; done
printf '# contactbench surface v1\n# nx=2 ny=2 lx=1e-06 ly=1e-06 periodic=true unit=m\n1e-9 2e-9\n3e-9 4e-9\n' \
  >"$work/corpus_topography/project.txt"
printf '1e-9 2e-9 3e-9\n4e-9 5e-9 6e-9\n' >"$work/corpus_topography/plain.txt"
[[ -d data/formats ]] && for file in data/formats/*; do head -c 16384 "$file" >"$work/corpus_topography/$(basename "$file")"; done
# Whole, valid files of the binary formats the project writes (the instrument files above are cut, so most
# of them reach only their readers' header checks; fuzz/seeds/README.md).
cp fuzz/seeds/*.x3p fuzz/seeds/*.npy "$work/corpus_topography/"
cp scenes/paper/*.toml scenes/studies/*.toml "$work/corpus_scene/"
for target in topography scene; do
  # The inputs, not their manifest of expected outcomes (tests/test_fuzz_regressions.cpp).
  [[ -d fuzz/regressions/$target ]] && find "fuzz/regressions/$target" -maxdepth 1 -type f ! -name EXPECTED \
    -exec cp {} "$work/corpus_$target/" \; || true
done

status=0
rows=()
for target in topography scene; do
  mkdir -p "$work/artifacts_$target"
  # The seeds, counted before libFuzzer adds its own inputs to the same folder; with --record, those the
  # release build reads without an error (as the fuzz target reads them: a size for the formats that carry
  # none), when that build exists.
  seeds=$(find "$work/corpus_$target" -maxdepth 1 -type f | wc -l)
  readable=-
  if [[ "$record" == "--record" && $target == topography && -x build/release/app/contactbench ]]; then
    readable=0
    for seed in "$work/corpus_$target"/*; do
      if build/release/app/contactbench stats "$seed" >/dev/null 2>&1 ||
        build/release/app/contactbench stats "$seed" --size 1e-5 >/dev/null 2>&1; then
        readable=$((readable + 1))
      fi
    done
  fi
  log="$work/$target.log"
  set +e
  # Bounded: 2 GiB of memory, 1 GiB for one allocation, 10 s for one input; inputs up to 64 KiB.
  "build/asan/fuzz/fuzz_$target" "$work/corpus_$target" -max_total_time="$seconds" -seed="$seed" -rss_limit_mb=2048 \
    -malloc_limit_mb=1024 -timeout=10 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$work/artifacts_$target/" >"$log" 2>&1
  code=$?
  set -e
  runs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' | tail -1)
  crashes=$(find "$work/artifacts_$target" -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' | wc -l)
  leaks=$(find "$work/artifacts_$target" -name 'leak-*' | wc -l)
  if [[ $code -ne 0 || $crashes -ne 0 || $leaks -ne 0 ]]; then
    status=1
    mkdir -p "fuzz/regressions/$target"
    cp "$work/artifacts_$target"/* "fuzz/regressions/$target/" 2>/dev/null || true
    echo "fuzz: $target found a problem (exit $code, seed $seed); inputs kept in fuzz/regressions/$target/," \
      "log $log; state each one's outcome in fuzz/regressions/$target/EXPECTED (the test suite says what to add)" >&2
    grep -m5 -E 'ERROR|SUMMARY|terminate' "$log" >&2 || true
  fi
  # libFuzzer's last status line: edges covered and the corpus it grew from the seeds.
  coverage=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+' || true)
  corpus=$(grep -oE 'corp: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+' || true)
  echo "fuzz: $target: ${runs:-0} executions in ${seconds} s, $crashes crashes, $leaks leaks"
  rows+=("| fuzz_$target | $seconds | ${runs:-0} | $seeds | $readable | ${corpus:-?} | ${coverage:-?} | $crashes | $leaks |")
done

if [[ "$record" == "--record" ]]; then
  commit=$(git rev-parse --short=12 HEAD)
  [[ -n "$(git status --porcelain --untracked-files=no)" ]] && commit="$commit-dirty"
  {
    echo "# Fuzzing record"
    echo
    echo "\`scripts/fuzz.sh $seconds --record\` (commit $commit, $(date -u +%Y-%m-%dT%H:%M:%SZ), 1 process per target,"
    echo "$(hostname) ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'))): libFuzzer with"
    echo "AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer, seeded with the project's files."
    echo
    echo "| target | seconds | executions | seed files | seeds read without error | corpus at the end | edges covered | crashes | leaks |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
    printf '%s\n' "${rows[@]}"
  } >results/fuzz.md.partial
  mv results/fuzz.md.partial results/fuzz.md
  echo "fuzz: wrote results/fuzz.md"
fi
exit $status
