#!/usr/bin/env bash
# Builds ewaview (installing missing packages first), then every target (the tests, the
# benchmarks they run), and runs every test: unit and render.
# Window tests run under Xvfb when no display is set.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
scripts/setup.sh "$build"
cmake --build "$build" -j"$(nproc)"  # setup.sh built the viewer and module only
run=(ctest --test-dir "$build" --output-on-failure -j"$(nproc)")
# CTest's output is kept in $build/ctest.log too: .ci/run counts the skipped tests from it.
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  xvfb-run -a -s "-screen 0 1280x800x24" "${run[@]}" | tee "$build/ctest.log"
else
  "${run[@]}" | tee "$build/ctest.log"
fi
