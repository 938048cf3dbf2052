#!/usr/bin/env bash
# Writes docs/images/window_tour.png: the window on the default volume under Xvfb, with numbered
# labels on the panel's sections, the transfer-function editor, the picture and its overlays,
# placed from the window's layout lines (EWAVIEW_PRINT_LAYOUT). Prints the labels' list.
# Usage: scripts/window_tour.sh [EWAVIEW_BINARY] [OUTPUT_PNG] [RAW_PNG] (RAW_PNG: the screenshot
# before labelling, kept); needs xvfb-run, xdotool, ImageMagick.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
binary="$(realpath "${1:-$root/build/ewaview}")"
output="$(realpath -m "${2:-$root/docs/images/window_tour.png}")"
raw="${3:+$(realpath -m "$3")}"
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" "$binary" "$output" ${raw:+"$raw"}
fi
width=1200; height=800
work="$(mktemp -d)"
pid=""
cleanup() { [ -n "$pid" ] && kill "$pid" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
mkdir -p "$work/config"  # no saved layout, window size or transfer function applies
(cd "$work" && EWAVIEW_CONFIG_DIR="$work/config" EWAVIEW_PRINT_LAYOUT=1 exec "$binary" \
  --resolution "$width,$height" >stdout 2>stderr) &
pid=$!
place_of() { grep "^$1 " "$work/stdout" 2>/dev/null | tail -1; }
wait_for() {  # wait_for COMMAND...: up to 3 minutes
  local start=$SECONDS
  until "$@"; do
    [ $((SECONDS - start)) -ge 180 ] && { echo "timed out: $*" >&2; cat "$work/stderr" >&2; exit 1; }
    sleep 0.5
  done
}
full() { [ "$(grep '^frame level ' "$work/stdout" 2>/dev/null | tail -1)" = "frame level 0" ]; }
window() { wid=$(xdotool search --onlyvisible --pid "$pid" --name '^ewaview$' 2>/dev/null | head -1); [ -n "$wid" ]; }
wait_for window
wait_for full
# The cursor on the big gear: the probe line names the point under it.
xdotool mousemove --window "$wid" 560 330; sleep 0.5; xdotool mousemove --window "$wid" 561 331
probed() { [ -n "$(place_of probe)" ]; }
wait_for probed
wait_for full
sleep 2
import -window "$wid" "$work/shot.png"
[ -z "$raw" ] || cp "$work/shot.png" "$raw"

draws=()
list=()
n=0
label() {  # label X Y TEXT: a numbered disc at X, Y
  n=$((n + 1))
  draws+=(-fill '#ffd21f' -stroke black -strokewidth 2 -draw "circle $1,$2 $(($1 + 13)),$2"
          -stroke none -fill black -draw "text $(($1 - (n > 9 ? 9 : 5))),$(($2 + 6)) '$n'")
  list+=("$n: $3")
}
header() {  # header ITEM TEXT: a label at the right end of a section's header
  local x y w h
  read -r _ x y w h <<<"$(place_of "$1")"
  label $((x + w - 16)) $((y + h / 2)) "$2"
}
read -r _ px py pw ph <<<"$(place_of panel)"
label $((px + pw - 60)) $((py + 40)) "the volume: its name, size and type (for a folder of series, a 4D or multi-channel file: the series list, frame and channel arrows); 'voxel spacing' folded below"
header section-file "File: open (Ctrl+O), save (Ctrl+S), reload (F5), reload when the file changes, recent files"
header section-view "View: render mode (composite, X-ray, MIP), transfer-function preset, shading, orientation axes, background, look-along views, copy view, reset camera, perspective and view angle"
header section-clip "Crop and clip (collapsed): the crop box and clipping planes from the view"
header section-bookmarks "Camera bookmarks (collapsed): named views to come back to"
header capture-header "Capture (collapsed): screenshot (F12) and its size, turntable and tour movies (PNG frames, MP4, WebM)"
header section-advanced "Advanced rendering (collapsed): the renderer's own knobs (renderer, filter, cutoff, depth cutoff, kernel width, classification, prefilter, slab floats and thickness, coarse slabs, coarser while moving, compositing and surfaces)"
header section-stats "Statistics: render and frame times, refinement, image size and level, GPU memory, splats and slabs"
label $((px + pw - 16)) $((py + ph - 18)) "mouse hints and 'keys (F1)': the list of keys"
read -r _ tx ty tw _ <<<"$(place_of tf-canvas)"
label $((tx + tw - 20)) $((ty + 20)) "Transfer-function editor: opacity points over the histogram, colour bar, undo/redo, presets, save, load, ParaView import"
label $(((px + pw + tx) / 2)) $((height / 2 + 150)) "The view: the volume (left drag orbits, right drag or wheel zooms, middle drag pans, double-click centres)"
label $((width - 115)) $((height - 150)) "Orientation axes (X switches them)"
label $((width - 455)) $((height - 16)) "Probe: the point under the cursor, its voxel and value"
mkdir -p "$(dirname "$output")"
convert "$work/shot.png" -font DejaVu-Sans-Bold -pointsize 15 "${draws[@]}" "$output"
printf '%s\n' "${list[@]}"
echo "wrote $output ($(stat -c %s "$output") bytes)" >&2
xdotool key --window "$wid" q
wait "$pid" || true
pid=""
