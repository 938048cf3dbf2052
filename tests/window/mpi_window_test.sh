#!/usr/bin/env bash
# ewaview-mpi's window under X: `mpirun -np 2 ewaview-mpi --synthetic ...` without --output opens
# the window on rank 0; the first full-quality picture (both ranks' bricks composited) must show
# the volume, an orbit drag must change it and settle at full quality again, the statistics must
# name both ranks, and Q must end every rank with status 0.
# Usage: mpi_window_test.sh "MPIEXEC FLAGS" EWAVIEW_MPI_BINARY OUTPUT_DIR.  Exit 77 (CTest skip)
# without X tools, or exit 1 when CI=true: CI must not pass by skipping.
set -uo pipefail
read -r -a mpiexec <<<"$1"
binary="$(realpath "$2")"
out="$3"
here="$(cd "$(dirname "$0")" && pwd)"
program=ewaview-mpi
tools="xdotool import compare convert"
# shellcheck source=harness.sh
source "$here/harness.sh"

width=1200; height=650
volume_crop="380x650+450+0"  # between the panel and the transfer-function editor
mkdir -p "$work/config"
(cd "$work" && EWAVIEW_CONFIG_DIR="$work/config" EWAVIEW_PRINT_LAYOUT=1 exec "${mpiexec[@]}" 2 \
  "$binary" --synthetic marschner-lobb:32 --tf "$here/ml_test.tf.json" --slab-thickness 4 \
  --resolution "$width,$height" >stdout 2>stderr) &
pid=$!
find_window() { wid=$(xdotool search --onlyvisible --name '^ewaview-mpi: 2 ranks$' 2>/dev/null | head -1); [ -n "$wid" ]; }
poll "the ewaview-mpi window" find_window
shot() { import -window "$wid" "$1" 2>/dev/null; }
frames() { grep -c '^frame level ' "$work/stdout"; }
full_quality() { [ "$(grep '^frame level ' "$work/stdout" | tail -1)" = "frame level 0" ]; }
coverage() { convert "$1" -crop "$2" +repage -colorspace gray -threshold 4% -format '%[fx:mean]' info:; }
differ() {
  convert "$1" -crop "$3" +repage "$work/da.png"; convert "$2" -crop "$3" +repage "$work/db.png"
  compare -metric AE -fuzz 2% "$work/da.png" "$work/db.png" null: 2>&1 | cut -d' ' -f1
}
greater() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b) }'; }

log "window up; waiting for full quality"
poll "the first full-quality picture" full_quality
sleep 1; shot "$out/0_start.png"
start_coverage=$(coverage "$out/0_start.png" "$volume_crop")
greater "$start_coverage" 0.05 || fail "the volume is not visible (coverage $start_coverage)"

log "orbit"
before=$(frames)
mx=560; my=450
xdotool mousemove --window "$wid" $mx $my; sleep 0.3
xdotool mousedown 1
for step in 1 2 3 4 5 6; do xdotool mousemove --window "$wid" $((mx + 15 * step)) $my; sleep 0.1; done
xdotool mouseup 1
moved() { [ "$(frames)" -gt "$before" ] && full_quality; }
poll "a full-quality picture after the orbit" moved
sleep 1; shot "$out/1_orbit.png"
orbit_diff=$(differ "$out/0_start.png" "$out/1_orbit.png" "$volume_crop")
greater "$orbit_diff" $((380 * 650 / 50)) || fail "the orbit changed only $orbit_diff pixels"

log "quit"
quit_window window
echo "PASS"
