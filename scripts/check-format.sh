#!/usr/bin/env bash
# Fails, listing the files, when any C++ source differs from what the project's .clang-format makes of it.
set -euo pipefail
cd "$(dirname "$0")/.."
format=$(command -v clang-format-14 || command -v clang-format) || { echo "check-format: clang-format not found" >&2; exit 1; }
mapfile -t files < <(git ls-files --cached --others --exclude-standard -- '*.cpp' '*.hpp' | while read -r f; do [[ -f "$f" ]] && echo "$f"; done)
bad=()
for file in "${files[@]}"; do
  "$format" --dry-run -Werror "$file" >/dev/null 2>&1 || bad+=("$file")
done
if [[ ${#bad[@]} -gt 0 ]]; then
  echo "check-format: not formatted (run scripts/format.sh): ${bad[*]}" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted"
