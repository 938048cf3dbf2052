#!/usr/bin/env bash
# Builds ewaview (installing missing packages first) and runs every test: unit and render.
# Window tests run under Xvfb when no display is set.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
scripts/setup.sh "$build"
run=(ctest --test-dir "$build" --output-on-failure -j"$(nproc)")
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  xvfb-run -a -s "-screen 0 1280x800x24" "${run[@]}"
else
  "${run[@]}"
fi
