#!/usr/bin/env bash
# Formats every C++ source with the project's .clang-format.
set -euo pipefail
cd "$(dirname "$0")/.."
format=$(command -v clang-format-14 || command -v clang-format)
git ls-files --cached --others --exclude-standard -- '*.cpp' '*.hpp' | while read -r f; do [[ -f "$f" ]] && "$format" -i "$f"; done
