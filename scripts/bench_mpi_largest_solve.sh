#!/usr/bin/env bash
# The largest solve this machine holds (issue 39, docs/mpi.md "Scaling model"): one cold load of the default
# solver, active_set with its nested coarse start, on surface A's spectrum at n x n points (default 16384^2,
# 268 million) on 2 ranks of one thread, to the scenes' tolerance 1e-8, no serial reference (rank 0 cannot
# hold a second copy), each rank under /usr/bin/time -v for its peak memory, CPU times and page faults.
# Records results/bench/mpi_largest_solve.md (OUT to choose another file). Needs the MPI build and about
# 12 GiB a rank at 16384^2; takes 13 minutes on the 2-core Intel Xeon of docs/mpi.md.
# Usage: [OUT=FILE] scripts/bench_mpi_largest_solve.sh [n]
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-16384}
if ! [[ "$n" =~ ^[1-9][0-9]*$ ]]; then
  echo "bench_mpi_largest_solve.sh: n must be a whole number of points a side (e.g. 16384), got '$n'" >&2
  exit 2
fi
cmake --preset release >/dev/null
cmake --build --preset release -j 2 --target bench_mpi >/dev/null
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1
commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- core bem mpi bench || commit="$commit+uncommitted"
machine="$(lscpu | sed -n 's/^Model name: *//p' | head -n 1) with $(nproc --all) cores"  # --all: nproc obeys OMP_NUM_THREADS
out=${OUT:-results/bench/mpi_largest_solve.md}
mkdir -p results/bench
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
load_before=$(cut -d ' ' -f 1-3 /proc/loadavg)
started=$(date -u +%Y-%m-%dT%H:%MZ)
# Each rank's /usr/bin/time report in its own file (OMPI_COMM_WORLD_RANK is set by mpiexec for each).
mpiexec --bind-to none -n 2 sh -c "exec /usr/bin/time -v -o $work/time.\$OMPI_COMM_WORLD_RANK \
  build/release/bench/bench_mpi --n $n --solver active_set --no-serial --tolerance 1e-8 --threads 1 \
  --repetitions 1" > "$work/row"
row=$(grep '^| 2 ' "$work/row")
field() { sed -n "s/^[[:space:]]*$1: *//p" "$work/time.$2"; }
iterations=$(echo "$row" | cut -d '|' -f 6 | tr -d ' ')
seconds=$(echo "$row" | cut -d '|' -f 7 | tr -d ' ')
per_iteration=$(awk -v s="$seconds" -v i="$iterations" 'BEGIN { printf "%.3g", s / i }')
gib() { awk -v k="$1" 'BEGIN { printf "%.2f GiB", k / 1048576 }'; }
{
  echo "# The largest solve: one load of the default solver on 2 ranks"
  echo
  echo "Made by \`${OUT:+OUT=$out }scripts/bench_mpi_largest_solve.sh $n\` at commit $commit, started $started,"
  echo "$machine, shared with other jobs: load average $load_before before and"
  echo "$(cut -d ' ' -f 1-3 /proc/loadavg) after (1, 5, 15 minutes; the two ranks are 2 of it)."
  echo "Surface A's spectrum (docs/theory.md section 2) on $n x $n points, periodic, one cold load at ~4 % contact"
  echo "to the scenes' tolerance 1e-8 (bench/bench_mpi.cpp --tolerance), the default solver, active_set, with its"
  echo "nested coarse start, 2 ranks x 1 thread (\`mpiexec --bind-to none -n 2 /usr/bin/time -v bench_mpi --n $n"
  echo "--solver active_set --no-serial --tolerance 1e-8 --threads 1 --repetitions 1\`); no serial reference."
  echo "Peak resident memory, CPU times and minor page faults are /usr/bin/time's for each rank's process (the"
  echo "shared-memory exchange window counts in both ranks' resident memory)."
  echo
  echo "| ranks | threads | n | solver | iterations | s/load | s/iteration | peak resident a rank | user + system s a rank | minor page faults a rank |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  echo "| 2 | 1 | $n | active_set | $iterations | $seconds | $per_iteration |" \
    "$(gib "$(field 'Maximum resident set size (kbytes)' 0)"), $(gib "$(field 'Maximum resident set size (kbytes)' 1)") |" \
    "$(field 'User time (seconds)' 0) + $(field 'System time (seconds)' 0), $(field 'User time (seconds)' 1) + $(field 'System time (seconds)' 1) |" \
    "$(field 'Minor (reclaiming a frame) page faults' 0), $(field 'Minor (reclaiming a frame) page faults' 1) |"
} > "$out"
cat "$out"
