#!/usr/bin/env bash
# Fails when a library includes a header it must not see (docs/architecture.md: core <- bem, core <- theories,
# (core, bem) <- mpi, only app (mpi/ in app/distributed_stages.cpp alone) and bench see everything; theories never includes bem, so each stays a check on the other), when a
# project header is included without the contactbench/ prefix, or when a tracked file reaches outside the
# project for its docs or data (the project stands on its own: docs/ and data/ are inside it).
set -euo pipefail
cd "$(dirname "$0")/.."
status=0
forbid() {  # forbid <folder> <library folders it must not include...>
  local folder=$1; shift
  [[ -d "$folder" ]] || return 0
  for library in "$@"; do
    if grep -rnE "#include \"contactbench/${library}/" "$folder" --include='*.hpp' --include='*.cpp'; then
      echo "check-layers: $folder/ must not include contactbench/$library/" >&2
      status=1
    fi
  done
}
forbid core bem theories app bench mpi
forbid bem theories app bench mpi
forbid theories bem app bench mpi
forbid app bench
# The app sees mpi/ in one file only, built with CB_WITH_MPI (app/distributed_stages.cpp): the serial build
# must not need it.
if grep -rlE '#include "contactbench/mpi/' app --include='*.hpp' --include='*.cpp' | grep -v '^app/distributed_stages.cpp$'; then
  echo "check-layers: only app/distributed_stages.cpp may include contactbench/mpi/" >&2
  status=1
fi
forbid mpi theories app bench

# Project headers are reached as "contactbench/<library>/x.hpp", the path they have once installed.
if git grep -nE '#include "(core|bem|theories|app|mpi)/' -- '*.cpp' '*.hpp'; then
  echo "check-layers: include project headers as \"contactbench/<library>/...\"" >&2
  status=1
fi

# Nothing tracked may name the team's reference shelf beside the checkout or read from it (the patterns below).
if git grep -nI -e '\.\./shared' -e 'shared/data/' -e 'shared/THEORY' -- ':!scripts/check-layers.sh'; then
  echo "check-layers: the files above point outside the project (the shelf beside the checkout); put what they need in docs/ or data/" >&2
  status=1
fi
exit $status
