#!/usr/bin/env bash
# What a load costs under mpiexec today against one process with the default solver (docs/mpi.md "The
# default solver"): the distributed preconditioned CG (what a scene must name to run as several ranks, since
# active_set has no distributed version) solved to the scenes' tolerance 1e-8, against the serial active_set
# of the same problem in the same run (bench/bench_mpi.cpp --tolerance), 1 rank x 1 thread against 1 thread
# and 2 ranks x 1 thread against 2 threads. Records results/bench/mpi_default_solver.md. Needs the MPI build.
# Usage: scripts/bench_mpi_default_solver.sh [sizes...]   (default: 1024 2048)
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release >/dev/null
cmake --build --preset release -j 2 --target bench_mpi >/dev/null
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=PASSIVE
commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- core bem mpi bench || commit="$commit+uncommitted"
machine="$(lscpu | sed -n 's/^Model name: *//p' | head -n 1) with $(nproc) cores"
out=results/bench/mpi_default_solver.md
mkdir -p results/bench
load_before=$(cut -d ' ' -f 1-3 /proc/loadavg)
rows=$(mktemp)
for n in ${@:-1024 2048}; do
  for ranks in 1 2; do
    # --bind-to none: OpenMPI binds each of 1 or 2 ranks to one core, which would put the reference's 2
    # threads (on rank 0) on one core.
    OMP_NUM_THREADS=$ranks mpiexec --oversubscribe --bind-to none -n "$ranks" build/release/bench/bench_mpi \
      --n "$n" --tolerance 1e-8 --solver preconditioned_cg --threads 1 --reference active_set \
      --reference-threads "$ranks" --repetitions 3 >> "$rows"
  done
done
{
  echo "# One load under mpiexec (preconditioned_cg) against one process (active_set)"
  echo
  echo "Made by \`scripts/bench_mpi_default_solver.sh ${*:-}\` at commit $commit on $(date -u +%Y-%m-%dT%H:%MZ),"
  echo "$machine, shared with other jobs: load average $load_before before and"
  echo "$(cut -d ' ' -f 1-3 /proc/loadavg) after (1, 5, 15 minutes), so the times are noisy; medians of 3 cold solves."
  echo "Surface A's spectrum (docs/theory.md section 2) on n x n points, periodic, ~4 % contact, solved to the"
  echo "scenes' tolerance 1e-8 (bench/bench_mpi.cpp --tolerance). The distributed solver runs on 'ranks' ranks x"
  echo "'threads' FFTW threads; the reference is the serial default solver, active_set, on 'ref threads' threads,"
  echo "timed in the same run (rank 0, the other rank asleep). 'ratio' is the distributed time of a load over the"
  echo "reference's: what running a scene under mpiexec costs today, where active_set is refused (docs/mpi.md)."
  echo
  echo "| ranks | threads | n | solver | iterations | s/load | reference | ref threads | ref iterations | ref s/load | ratio |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  cat "$rows"
} > "$out"
rm -f "$rows"
cat "$out"
