#!/usr/bin/env bash
# The installed package works for another project: installs the build tree given as $1 into a temporary prefix,
# then configures, builds and runs examples/consumer against it (find_package(contactbench), contactbench::bem).
# Also checks that the installed program runs, that the headers sit under include/contactbench/, and, for a
# build with MPI, that contactbench::mpi is installed (the consumer's configure then finds MPI through the
# package's config).
# Usage: scripts/check-install.sh BUILD_DIR   (the test command runs it as the CTest test install_and_consume)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: check-install.sh BUILD_DIR}
work=$(mktemp -d "${TMPDIR:-/tmp}/contactbench-install.XXXXXX")
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
for header in core/surface.hpp bem/bem_solver.hpp theories/plateau_model.hpp; do
  [[ -f "$work/prefix/include/contactbench/$header" ]] || { echo "check-install: missing include/contactbench/$header" >&2; exit 1; }
done
# Built with MPI (CB_WITH_MPI): the distributed library is installed too, with its headers and target.
if grep -q '^CB_WITH_MPI:BOOL=ON' "$build/CMakeCache.txt"; then
  [[ -f "$work/prefix/include/contactbench/mpi/distributed_sweep.hpp" ]] ||
    { echo "check-install: missing include/contactbench/mpi/distributed_sweep.hpp" >&2; exit 1; }
  grep -qs 'contactbench::mpi' "$work/prefix"/lib*/cmake/contactbench/contactbenchTargets.cmake ||
    { echo "check-install: the package does not define contactbench::mpi" >&2; exit 1; }
fi
"$work/prefix/bin/contactbench" --version

# The consumer sees only the prefix: nothing of the source or build tree is on its paths.
cmake -S examples/consumer -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  >"$work/configure.log" || { cat "$work/configure.log" >&2; exit 1; }
cmake --build "$work/consumer" -j 2 >"$work/build.log" || { cat "$work/build.log" >&2; exit 1; }
if grep -rqs -e "$(pwd)/core" -e "$(pwd)/bem" -e "$(realpath "$build")/include" "$work/consumer/CMakeFiles"; then
  echo "check-install: the consumer's build reached into the source or build tree" >&2
  exit 1
fi
OMP_NUM_THREADS=1 "$work/consumer/consumer"
