# The window tests' shared set-up, sourced after the script sets `program` (its name in
# messages), `tools` (the X tools it needs), `out` (its output folder) and, optionally,
# `timeout` (seconds a poll waits; 180 by default: a loaded 2-core llvmpipe machine) and
# `on_fail` (a function run before a failure exits). Without X it skips (exit 77, CTest's skip)
# or, with CI=true, fails: CI must not pass by skipping. Without a display it runs the script
# again under Xvfb. It then gives the script `work` (a scratch folder removed at exit), `pid`
# (set it to the program's; killed at exit), fail, log, poll and quit_window.
skip() {
  case "${CI:-}" in
    "" | 0 | false) echo "SKIP (would fail with CI=true): $*"; exit 77 ;;
    *) echo "FAIL: CI=true and the window test cannot run: $*"; exit 1 ;;
  esac
}
for tool in $tools; do
  command -v "$tool" >/dev/null || skip "$tool not installed (scripts/setup.sh installs it)"
done
if [ -z "${DISPLAY:-}" ]; then
  command -v xvfb-run >/dev/null || skip "no DISPLAY and no xvfb-run"
  exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" "$@"
fi
xdotool getdisplaygeometry >/dev/null 2>&1 || skip "cannot reach the X server on DISPLAY=$DISPLAY"
mkdir -p "$out"
rm -f "$out"/*.png
work="$(mktemp -d)"
pid=""
cleanup() {
  [ -n "$pid" ] && kill "$pid" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*"
  echo "--- $program stdout/stderr (tail):"
  tail -n 80 "$work/stdout" "$work/stderr" 2>/dev/null
  [ -n "${on_fail:-}" ] && "$on_fail"
  exit 1
}
log() { echo "[${SECONDS}s] $*"; }
timeout=${timeout:-180}
poll() {  # poll DESCRIPTION COMMAND...: waits up to `timeout` seconds for COMMAND to succeed
  local what="$1"; shift
  local start=$SECONDS
  until "$@"; do
    [ $((SECONDS - start)) -ge $timeout ] && fail "timed out after ${timeout}s waiting for $what"
    kill -0 "$pid" 2>/dev/null || fail "$program exited while waiting for $what"
    sleep 0.3
  done
}

# Quits the window `wid` with Q: the program must end within a minute, with status 0.
quit_window() {  # quit_window NAME
  xdotool key --window "$wid" q
  local start=$SECONDS rc
  while kill -0 "$pid" 2>/dev/null; do
    [ $((SECONDS - start)) -ge 60 ] && fail "Q did not close the $1"
    sleep 0.3
  done
  wait "$pid"; rc=$?; pid=""
  [ "$rc" -eq 0 ] || fail "the $1's $program exited with $rc"
}
