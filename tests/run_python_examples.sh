#!/usr/bin/env bash
# Runs every example of examples/python/ as a user would (examples/python/*.py say how), each in a fresh
# temporary working folder, which is all they may write to: the examples must run on the current module, and
# running them must leave the source tree as it was. Without --out the tutorial's steps put their plots in a new
# temporary folder (examples/python/tutorial.py), which TMPDIR places inside the working folder, so that it goes
# with it (they had left a folder in /tmp on every run).
# Usage: tests/run_python_examples.sh PYTHON MODULE_DIR   (registered as the CTest test python_examples)
set -euo pipefail
python=${1:?usage: run_python_examples.sh PYTHON MODULE_DIR}
module=${2:?usage: run_python_examples.sh PYTHON MODULE_DIR}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
# What the source tree holds where an example could write (its own folder, the data it reads, the top level):
# names, sizes and times.
snapshot() {
  find "$source_dir/examples" "$source_dir/data" "$source_dir" -maxdepth 2 -not -path '*/build/*' -not -path '*/.git/*' \
    -type f -printf '%p %s %T@\n' | sort
}
before=$(snapshot)
status=0
for example in "$source_dir"/examples/python/*.py; do
  work=$(mktemp -d "${TMPDIR:-/tmp}/contactbench-example.XXXXXX")
  echo "python_examples: $(basename "$example") in $work"
  if ! (cd "$work" && TMPDIR="$work" PYTHONPATH="$module" OMP_WAIT_POLICY=PASSIVE MPLBACKEND=Agg "$python" "$example"); then
    echo "python_examples: $(basename "$example") failed" >&2
    status=1
  fi
  ls -A "$work"
  rm -rf "$work"
done
after=$(snapshot)
if [[ "$before" != "$after" ]]; then
  echo "python_examples: the examples wrote into the source tree:" >&2
  diff <(echo "$before") <(echo "$after") >&2 || true
  status=1
fi
exit $status
