#!/usr/bin/env bash
# Fails when a library includes a header it must not see (ARCHITECTURE.md: core <- bem, core <- theories,
# only app and bench see everything; theories never includes bem, so each stays a check on the other).
set -euo pipefail
cd "$(dirname "$0")/.."
status=0
forbid() {  # forbid <folder> <include prefixes...>
  local folder=$1; shift
  [[ -d "$folder" ]] || return 0
  for prefix in "$@"; do
    if grep -rnE "#include \"${prefix}/" "$folder" --include='*.hpp' --include='*.cpp'; then
      echo "check-layers: $folder/ must not include $prefix/" >&2
      status=1
    fi
  done
}
forbid core bem theories app bench
forbid bem theories app bench
forbid theories bem app bench
forbid app bench
exit $status
