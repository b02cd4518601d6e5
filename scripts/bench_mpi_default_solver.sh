#!/usr/bin/env bash
# What a load costs under mpiexec against one process with the default solver (docs/mpi.md "The default
# solver"): the distributed solvers (the default, active_set, and preconditioned_cg, what a scene had to name
# under mpiexec before active_set was distributed) solved to the scenes' tolerance 1e-8, against the serial
# active_set of the same problem in the same run (bench/bench_mpi.cpp --tolerance), 1 rank x 1 thread against
# 1 thread and 2 ranks x 1 thread against 2 threads. Records results/bench/mpi_default_solver.md. Needs the
# MPI build.
# Usage: [SOLVERS="active_set preconditioned_cg"] [RANKS="1 2"] [EXCHANGES="auto"] \
#          scripts/bench_mpi_default_solver.sh [sizes...]
#        (default sizes: 1024 2048; RANKS: the rank counts timed, default both; EXCHANGES: the slab engine's
#        transports timed one after the other in each row's place, CONTACTBENCH_MPI_EXCHANGE's values, e.g.
#        "shared_memory messages"; OUT: the record, default results/bench/mpi_default_solver.md)
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release >/dev/null
cmake --build --preset release -j 2 --target bench_mpi >/dev/null
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=PASSIVE
commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- core bem mpi bench || commit="$commit+uncommitted"
machine="$(lscpu | sed -n 's/^Model name: *//p' | head -n 1) with $(nproc) cores"
out=${OUT:-results/bench/mpi_default_solver.md}
mkdir -p results/bench
load_before=$(cut -d ' ' -f 1-3 /proc/loadavg)
rows=$(mktemp)
solvers=${SOLVERS:-active_set preconditioned_cg}
for n in ${@:-1024 2048}; do
  for solver in $solvers; do
    for ranks in ${RANKS:-1 2}; do
      for exchange in ${EXCHANGES:-auto}; do
        # --bind-to none: OpenMPI binds each of 1 or 2 ranks to one core, which would put the reference's 2
        # threads (on rank 0) on one core.
        CONTACTBENCH_MPI_EXCHANGE=$exchange OMP_NUM_THREADS=$ranks mpiexec --oversubscribe --bind-to none \
          -n "$ranks" build/release/bench/bench_mpi --n "$n" --tolerance 1e-8 --solver "$solver" --threads 1 \
          --reference active_set --reference-threads "$ranks" --repetitions 3 | sed "s/\$/ $exchange |/" >> "$rows"
      done
    done
  done
done
{
  echo "# One load under mpiexec against one process (active_set)"
  echo
  echo "Made by \`${OUT:+OUT=$out }SOLVERS=\"$solvers\" RANKS=\"${RANKS:-1 2}\" EXCHANGES=\"${EXCHANGES:-auto}\" scripts/bench_mpi_default_solver.sh ${*:-}\` at commit $commit on $(date -u +%Y-%m-%dT%H:%MZ),"
  echo "$machine, shared with other jobs: load average $load_before before and"
  echo "$(cut -d ' ' -f 1-3 /proc/loadavg) after (1, 5, 15 minutes), so the times are noisy; medians of 3 cold solves."
  echo "Surface A's spectrum (docs/theory.md section 2) on n x n points, periodic, ~4 % contact, solved to the"
  echo "scenes' tolerance 1e-8 (bench/bench_mpi.cpp --tolerance). The distributed solver runs on 'ranks' ranks x"
  echo "'threads' FFTW threads; the reference is the serial default solver, active_set, on 'ref threads' threads,"
  echo "timed in the same run (rank 0, the other rank asleep). 'ratio' is the distributed time of a load over the"
  echo "reference's: what running a scene under mpiexec costs (docs/mpi.md, \"What a distributed iteration costs\":"
  echo "the passes of an iteration counted, fused as the serial method's since issue 39's second item)."
  echo "'exchanges' is the time rank 0 spent inside MPI's all-to-all exchanges during the distributed solve, the"
  echo "global transposes timed inside it (bench/mpi_call_clock.hpp: MPI's profiling interface), 'reductions' the"
  echo "time inside its sums; each includes the wait for the other rank, and the share is of the solve's time."
  echo "'exchange' is the slab engine's transport (CONTACTBENCH_MPI_EXCHANGE, docs/mpi.md \"Exchanges in shared"
  echo "memory\"): auto takes shared memory when the ranks share a machine; in shared memory the exchanges' time is"
  echo "the barriers' (the wait for the other rank), by messages the all-to-alls'."
  echo
  echo "| ranks | threads | n | solver | iterations | s/load | reference | ref threads | ref iterations | ref s/load | ratio | exchanges s | share | reductions s | share | exchange |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  cat "$rows"
} > "$out"
rm -f "$rows"
cat "$out"
