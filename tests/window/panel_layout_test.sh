#!/usr/bin/env bash
# Panel layout window test: starts ewaview on its default volume under X and reads the panel's
# layout lines (EWAVIEW_PRINT_LAYOUT): the sections come in the order a person exploring a volume
# needs them (File, View, Crop and clip, bookmarks, Capture, then Advanced rendering and the
# statistics), the renderer's knobs (cutoff, depth cutoff, kernel width, prefilter, slab floats)
# are drawn only once "Advanced rendering" is opened, below its header, the panel leaves the
# picture room, and the default volume fills a good part of the picture.
# Usage: panel_layout_test.sh EWAVIEW_BINARY OUTPUT_DIR.  Exit 77 (CTest skip) without X tools,
# or exit 1 when CI=true: CI must not pass by skipping.
set -uo pipefail
binary="$(realpath "$1")"
out="$2"
here="$(cd "$(dirname "$0")" && pwd)"
program=ewaview
tools="xdotool import convert"
# shellcheck source=harness.sh
source "$here/harness.sh"

# Tall enough for the whole panel with its statistics (no scrolling to reach a header).
width=1100; height=780
mkdir -p "$work/config"  # a scratch settings folder: no saved layout or window size applies
(cd "$work" && EWAVIEW_CONFIG_DIR="$work/config" EWAVIEW_PRINT_LAYOUT=1 exec "$binary" \
  --resolution "$width,$height" >stdout 2>stderr) &
pid=$!
place_of() { grep "^$1 " "$work/stdout" 2>/dev/null | tail -1; }
y_of() { place_of "$1" | cut -d' ' -f3; }
has() { [ -n "$(place_of "$1")" ]; }
poll "the statistics header's layout line" has section-stats
poll "the first full-quality picture" grep -q '^frame level 0$' "$work/stdout"
find_window() { wid=$(xdotool search --onlyvisible --pid "$pid" --name '^ewaview$' 2>/dev/null | head -1); [ -n "$wid" ]; }
poll "the ewaview window" find_window
sleep 1  # the panel settles (its width follows its widest line)

# The sections, top to bottom, in this order.
previous="" previous_y=-1
for section in section-file section-view section-clip section-bookmarks capture-header \
  section-advanced section-stats; do
  has "$section" || fail "no layout line for $section"
  y=$(y_of "$section")
  [ "$y" -gt "$previous_y" ] || fail "$section (y $y) is not below $previous (y $previous_y)"
  previous="$section" previous_y="$y"
done
# The renderer's knobs are not drawn while their section is closed.
knobs="knob-cutoff knob-depth-cutoff knob-kernel-width knob-prefilter knob-slab-floats"
for knob in $knobs; do
  has "$knob" && fail "$knob is drawn with Advanced rendering closed ($(place_of "$knob"))"
done
# The panel leaves the picture the window's middle (the scripted window test's crops too).
read -r _ px py pw ph <<<"$(place_of panel)"
[ $((px + pw)) -le 405 ] || fail "the panel reaches x $((px + pw)), over the picture (405 at most)"
[ $((py + ph)) -le "$height" ] || fail "the panel ($ph px high) does not fit the window"
# The default volume fills a good part of the picture between the panel and the editor.
import -window "$wid" "$out/panel_start.png" 2>/dev/null || fail "no screenshot of the window"
coverage=$(convert "$out/panel_start.png" -crop "300x$((height - 40))+415+20" +repage \
  -colorspace gray -threshold 4% -format '%[fx:mean]' info:)
awk -v c="$coverage" 'BEGIN { exit !(c > 0.15) }' ||
  fail "the default volume covers only $coverage of the picture's middle"

# Opened, "Advanced rendering" shows the knobs below its header.
read -r _ ax ay _ ah <<<"$(place_of section-advanced)"
xdotool mousemove --window "$wid" $((ax + 40)) $((ay + ah / 2)); sleep 0.3; xdotool click 1
poll "the cutoff slider's layout line" has knob-cutoff
for knob in $knobs; do
  poll "$knob's layout line" has "$knob"
  [ "$(y_of "$knob")" -gt "$(y_of section-advanced)" ] ||
    fail "$knob (y $(y_of "$knob")) is not under Advanced rendering (y $(y_of section-advanced))"
done
import -window "$wid" "$out/panel_advanced.png" 2>/dev/null

quit_window window
echo "PASS: sections in order; knobs only under Advanced rendering; panel ${pw}x${ph}; default volume coverage $coverage"
