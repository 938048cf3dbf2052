#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/*_fuzzer.cpp) with clang, ASan and UBSan in their own
# folder (default build-fuzz) and runs each for SECONDS (default 30), starting from the seeds in
# fuzz/corpus/NAME plus what earlier runs in that folder found. A crash, sanitizer report,
# leak, hang (10 s an input) or out-of-memory (2 GiB) stops with its input saved as
# BUILD/crashes/NAME-...: copy it into tests/data/fuzz/NAME/ once fixed, so the unit tests
# replay it for ever.   Usage: scripts/fuzz.sh [SECONDS] [BUILD] [NAME...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
build="${2:-build-fuzz}"
shift $(( $# > 2 ? 2 : $# ))
# Line tables only: a crash's stack keeps its file:line, the build is quicker.
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEWA_FUZZ=ON \
  -DEWA_BUILD_TESTS=OFF -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" >/dev/null
nice cmake --build "$build" -j"$(nproc)" --target ewa_fuzzers
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for src in fuzz/*_fuzzer.cpp; do n="$(basename "$src" .cpp)"; names+=("${n%_fuzzer}"); done
fi
mkdir -p "$build/crashes"
# The sanitizer build's leak suppressions (libraries' own leaks, each with its reason).
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
# Fuzzes one target; its report goes to BUILD/NAME.out, and BUILD/NAME.failed marks a failure.
fuzz_one() {
  local name="$1" corpus="$build/corpus/$1"
  mkdir -p "$corpus"
  rm -f "$build/$name.failed"
  {
    echo "== fuzzing $name for ${seconds}s"
    if ! "$build/${name}_fuzzer" "$corpus" "fuzz/corpus/$name" -max_total_time="$seconds" \
        -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
        -artifact_prefix="$build/crashes/$name-" 2>"$build/$name.log"; then
      echo "fuzz: $name failed; the input is in $build/crashes/, the log in $build/$name.log"
      tail -n 40 "$build/$name.log"
      touch "$build/$name.failed"
    fi
    grep -E "^stat::(number_of_executed_units|new_units_added|peak_rss_mb)" "$build/$name.log" |
      tr '\n' ' '
    echo
  } >"$build/$name.out"
}
# A fuzzer runs on one core: one target a core at once, each still its full SECONDS.
for name in "${names[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do wait -n || true; done
  fuzz_one "$name" &
done
wait
status=0
for name in "${names[@]}"; do
  cat "$build/$name.out"
  [ ! -e "$build/$name.failed" ] || status=1
done
exit $status
