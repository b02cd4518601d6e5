#!/usr/bin/env bash
# Runs the distributed solver's benchmark (bench/bench_mpi.cpp) over ranks x threads x grid sizes and records
# results/bench/mpi.md (docs/mpi.md), stamped with the commit, date, machine and this command. Needs the MPI
# build (CB_WITH_MPI); as root, OpenMPI needs OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM), set here. Takes ~10 minutes.
# Usage: scripts/bench_mpi.sh [sizes...]   (default: 1024 2048 4096)
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
  echo "largest rank's solver memory (DistributedPolonskyKeer::bytes), 'serial MiB' an estimate of the serial"
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
      OMP_NUM_THREADS=$threads mpiexec --oversubscribe -n "$ranks" build/release/bench/bench_mpi --n "$n" \
        --iterations "$iterations" --threads "$threads" >> "$out.tmp"
    done
  done
done
mv "$out.tmp" "$out"
cat "$out"
