#!/usr/bin/env bash
# Runs the distributed solver's benchmark (bench/bench_mpi.cpp) over ranks x threads x grid sizes and records
# results/bench/mpi.md (docs/mpi.md), stamped with the commit, date, machine and this command. Needs the MPI
# build (CB_WITH_MPI); as root, OpenMPI needs OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM), set here. Takes ~10 minutes.
# Usage: scripts/bench_mpi.sh [sizes...]   (default: 1024 2048 4096)
# CB_BENCH_MPI_LARGEST (default 16384; empty: skip) adds the largest grid this machine holds: 2 ranks x 1
# thread, 2 iterations, without the serial reference (which would not fit beside it), with each rank's peak
# resident memory measured by /usr/bin/time.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target bench_mpi >/dev/null
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=PASSIVE
commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- core bem mpi bench || commit="$commit+uncommitted"
machine="$(lscpu | sed -n 's/^Model name: *//p' | head -n 1) with $(nproc) cores"
out=results/bench/mpi.md
mkdir -p results/bench
{
  echo "# The distributed solver: seconds per iteration, transposes, bytes per rank"
  echo
  echo "Made by \`scripts/bench_mpi.sh ${*:-}\` at commit $commit on $(date -u +%Y-%m-%d), $machine, shared with"
  echo "other jobs (timings are noisy: medians of 3 cold solves of a fixed number of iterations; the serial solver"
  echo "of the same problem is the reference, timed in the same run). Plain Polonsky-Keer, surface A's spectrum"
  echo "(docs/theory.md section 2) on n x n points, periodic, ~4 % contact. 'transposes' is the time of FFTW-MPI's"
  echo "global transposes an iteration would take (4 a plain iteration), timed on their own; 'MiB/rank' is the"
  echo "largest rank's solver memory (DistributedBemSolver::bytes), 'serial MiB' an estimate of the serial"
  echo "solver's arrays. Threads are FFTW's threads a rank (the element-wise passes run on one)."
  echo
  echo "| ranks | threads | n | solver | s/iteration | serial s/iteration | ratio | transposes s/iteration | share | MiB/rank | serial MiB |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
} > "$out.tmp"
for n in ${@:-1024 2048 4096}; do
  iterations=10
  [[ $n -ge 4096 ]] && iterations=4
  for ranks in 1 2; do
    for threads in 1 2; do
      # --bind-to none: OpenMPI binds each of 1 or 2 ranks to one core, where 2 threads would share it.
      OMP_NUM_THREADS=$threads mpiexec --oversubscribe --bind-to none -n "$ranks" build/release/bench/bench_mpi --n "$n" \
        --iterations "$iterations" --threads "$threads" >> "$out.tmp"
    done
  done
done
largest=${CB_BENCH_MPI_LARGEST-16384}
if [[ -n "$largest" ]]; then
  peaks=$(mktemp)
  OMP_NUM_THREADS=1 mpiexec --oversubscribe -n 2 /usr/bin/time -a -o "$peaks" -f "%M" build/release/bench/bench_mpi \
    --n "$largest" --iterations 2 --repetitions 1 --threads 1 --no-serial >> "$out.tmp"
  {
    echo
    echo "The last row is the largest grid run here ($largest², double precision, 2 ranks): one cold solve of 2"
    echo "iterations, without the serial reference, which would not fit beside it. Peak resident memory per rank"
    echo "(/usr/bin/time): $(sort -n "$peaks" | awk '{printf "%s%.2f GiB", (NR > 1 ? ", " : ""), $1 / 1048576}')."
    echo "$(awk '{ total += $1 } END { printf "Both ranks together: %.1f GiB of the machine'"'"'s 24 GiB; the next size up needs single precision,", total / 1048576 }' "$peaks")"
    echo "which is not distributed yet (docs/mpi.md)."
  } >> "$out.tmp"
  rm -f "$peaks"
fi
mv "$out.tmp" "$out"
cat "$out"
