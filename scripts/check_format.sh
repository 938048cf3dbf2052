#!/usr/bin/env bash
# Checks that every C++ file under src/, bench/ and tests/ is formatted as .clang-format says
# (clang-format --dry-run -Werror); `clang-format -i FILE` fixes one.
# Usage: scripts/check_format.sh
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || {
  echo "check_format: clang-format missing (apt-get install clang-format)" >&2
  exit 1
}
find src bench tests -type f \( -name '*.cpp' -o -name '*.h' \) -not -path 'tests/data/*' -print0 |
  sort -z | xargs -0 clang-format --style=file --dry-run -Werror
echo "check_format: src/, bench/ and tests/ are formatted"
