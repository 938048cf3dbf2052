#!/usr/bin/env bash
# Scripted window test: starts the real ewaview under X, replays an orbit drag, a scroll zoom, a
# transfer-function drag, a double-click on the volume (the probe and the new centre), a mark and
# the axes key with xdotool, and checks the screenshots change as they should; then
# checks that an orbit drag is answered while a full-quality frame is being refined, that
# Page Down and Page Up page through a 4D file's frames, and the channels, saving, --watch,
# screenshots, the Capture section's Tour through two camera bookmarks and its Turntable, and a
# DICOM folder's series list.
# Usage: window_test.sh EWAVIEW_BINARY OUTPUT_DIR.  Exit 77 (CTest skip) without X tools, or
# exit 1 when CI=true: CI must not pass by skipping.
set -uo pipefail
binary="$(realpath "$1")"
out="$2"
fixture="${3:+$(realpath "$3")}"  # writes a DICOM folder of two series (ewa_window_fixture)
here="$(cd "$(dirname "$0")" && pwd)"
program=ewaview
tools="xdotool import compare convert"
# shellcheck source=harness.sh
source "$here/harness.sh"

# Window 1100x600: the control panel covers x < ~405, the editor x >= 714; the volume region
# between them is what the camera checks look at.
width=1100; height=600
# EWA_WINDOW_TEST_SPLATTER (scripts/sanitize.sh: raster) picks every window's splatter; unset,
# auto's (on llvmpipe the CPU splatter).
splatter=()
[ -n "${EWA_WINDOW_TEST_SPLATTER:-}" ] && splatter=(--splatter "$EWA_WINDOW_TEST_SPLATTER")
volume_crop="290x600+415+0"
mkdir -p "$work/config"  # a scratch settings folder: no saved layout or window size applies
(cd "$work" && EWAVIEW_CONFIG_DIR="$work/config" EWAVIEW_PRINT_LAYOUT=1 exec "$binary" "${splatter[@]}" --synthetic marschner-lobb:32 \
  --tf "$here/ml_test.tf.json" --slab-thickness 4 --resolution "$width,$height" >stdout 2>stderr) &
pid=$!
have_layout() { grep -q '^tf-canvas ' "$work/stdout"; }
poll "the editor's layout line" have_layout
find_window() { wid=$(xdotool search --onlyvisible --pid "$pid" --name '^ewaview$' 2>/dev/null | head -1); [ -n "$wid" ]; }
poll "the ewaview window" find_window
read -r _ cx cy cw ch < <(grep '^tf-canvas ' "$work/stdout" | tail -1)

shot() { import -window "$wid" "$1" 2>/dev/null; }
# Pixels that differ (by more than 2%) between two images, optionally in a crop.
differ() {  # differ A B [CROP]
  local a="$1" b="$2"
  if [ -n "${3:-}" ]; then
    convert "$1" -crop "$3" +repage "$work/da.png"; convert "$2" -crop "$3" +repage "$work/db.png"
    a="$work/da.png"; b="$work/db.png"
  fi
  compare -metric AE -fuzz 2% "$a" "$b" null: 2>&1 | cut -d' ' -f1
}
mean() { convert "$1" -crop "$2" +repage -colorspace gray -format '%[fx:mean]' info:; }
# Fraction of the crop that shows the volume (brighter than the black background).
coverage() { convert "$1" -crop "$2" +repage -colorspace gray -threshold 4% -format '%[fx:mean]' info:; }
greater() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b) }'; }

# The viewer prints "frame level L" for every picture it draws: the last one must be full quality
# (level 0), not a coarse level still waiting to be refined.
full_quality() { [ "$(grep '^frame level ' "$work/stdout" | tail -1)" = "frame level 0" ]; }

# Takes screenshots until the picture differs from `before` (in `crop`), the last frame drawn is
# full quality and the picture holds still for two shots in a row; leaves the result in `$1`.
settled() {  # settled RESULT BEFORE CROP
  local result="$1" before="$2" crop="$3" start=$SECONDS
  shot "$work/a.png"
  until [ "$(differ "$before" "$work/a.png" "$crop")" -gt 0 ]; do
    [ $((SECONDS - start)) -ge $timeout ] && fail "no change on screen after ${timeout}s ($result)"
    sleep 0.3; shot "$work/a.png"
  done
  while :; do
    sleep 0.5; shot "$work/b.png"
    [ "$(differ "$work/a.png" "$work/b.png")" -eq 0 ] && full_quality && break
    [ $((SECONDS - start)) -ge $timeout ] && fail "picture never settled ($result)"
    cp "$work/b.png" "$work/a.png"
  done
  cp "$work/b.png" "$result"
}

# Starts ewaview on FILE (relative to the scratch folder) with its own settings folder NAME and
# EWAVIEW_PRINT_LAYOUT, fresh stdout and stderr logs, and waits for its window.
start_window() {  # start_window NAME FILE [OPTION...]
  : >"$work/stdout"; : >"$work/stderr"
  mkdir -p "$work/$1"
  local config="$work/$1" file="$2"
  shift 2
  (cd "$work" && EWAVIEW_CONFIG_DIR="$config" EWAVIEW_PRINT_LAYOUT=1 exec "$binary" "${splatter[@]}" "$file" \
    --resolution "$width,$height" "$@" >stdout 2>stderr) &
  pid=$!
  poll "the ewaview window" find_window
}

# Presses KEY, waits for stderr to log LINE and for the picture to settle in RESULT (changed
# from BEFORE in the ball's crop), which must show the ball shrunk below 0.6 times its coverage,
# left in $shrunk.
page_shrinks() {  # page_shrinks KEY LINE BEFORE RESULT
  xdotool key --window "$wid" "$1"
  logged() { grep -q "^ewaview: $1 in" "$work/stderr"; }
  poll "'$2' on $1" logged "$2"
  settled "$4" "$3" "$frames_crop"
  local c0 c1
  c0=$(coverage "$3" "$frames_crop"); c1=$(coverage "$4" "$frames_crop")
  greater "$(awk -v a="$c0" 'BEGIN { print a * 0.6 }')" "$c1" ||
    fail "$1 did not show the smaller ball ($2: coverage $c0 -> $c1)"
  shrunk="$c1"
}

# First picture: wait until the volume is drawn and the window is still.
black="$work/black.png"
convert -size "${width}x${height}" xc:black "$black"
log "window up; waiting for the first picture"
settled "$out/0_start.png" "$black" "$volume_crop"
start_coverage=$(coverage "$out/0_start.png" "$volume_crop")
greater "$start_coverage" 0.05 || fail "the volume is not visible at start (coverage $start_coverage)"

log "first picture"
# Idle: nothing happens, nothing changes.
sleep 2; shot "$out/1_idle.png"
idle_diff=$(differ "$out/0_start.png" "$out/1_idle.png")
[ "$idle_diff" -eq 0 ] || fail "an idle window changed ($idle_diff pixels)"

log "idle checked"
# Orbit: left-drag across the volume.
mx=$((415 + 145)); my=300
xdotool mousemove --window "$wid" $mx $my; sleep 0.3
xdotool mousedown 1
for step in 1 2 3 4 5 6; do xdotool mousemove --window "$wid" $((mx + 15 * step)) $my; sleep 0.1; done
xdotool mouseup 1
settled "$out/2_orbit.png" "$out/1_idle.png" "$volume_crop"
orbit_diff=$(differ "$out/1_idle.png" "$out/2_orbit.png" "$volume_crop")
greater "$orbit_diff" $((290 * 600 / 50)) || fail "orbit changed only $orbit_diff pixels of the volume region"

log "orbit checked"
# Zoom out: three wheel notches towards the user make the volume smaller.
xdotool mousemove --window "$wid" $mx $my; sleep 0.3
xdotool click --repeat 3 --delay 150 5
settled "$out/3_zoom.png" "$out/2_orbit.png" "$volume_crop"
before=$(coverage "$out/2_orbit.png" "$volume_crop"); after=$(coverage "$out/3_zoom.png" "$volume_crop")
greater "$before" "$(awk -v a="$after" 'BEGIN { print a * 1.15 }')" ||
  fail "zooming out did not shrink the volume (coverage $before -> $after)"

log "zoom checked"
# Ctrl+C copies the view as options (the panel and stderr show them): rendered headless with
# them, the picture is the one in the window, right of the panel.
picture_crop="220x600+470+0"
xdotool key --window "$wid" ctrl+c
copied() { grep -q '^ewaview: view copied: ' "$work/stderr"; }
poll "the view copied with Ctrl+C" copied
view_options=$(grep '^ewaview: view copied: ' "$work/stderr" | tail -1 | sed 's/^ewaview: view copied: //')
# shellcheck disable=SC2086  # the options are words
"$binary" --synthetic marschner-lobb:32 --tf "$here/ml_test.tf.json" --slab-thickness 4 \
  $view_options -o "$out/3_headless.png" 2>>"$work/stderr" || fail "the copied view ($view_options) does not render"
view_diff=$(differ "$out/3_zoom.png" "$out/3_headless.png" "$picture_crop")
[ "$view_diff" -le $((220 * 600 / 100)) ] ||
  fail "the copied view renders another picture ($view_diff px differ; $view_options)"
log "copied view checked ($view_diff px differ)"
# Transfer function: drag the opacity point at value 0.5 (alpha 0: the plot's bottom edge, half
# way across) up to alpha 0.6. Values between 0 and 0.5 become visible: more and brighter pixels.
px=$((cx + cw / 2)); py=$((cy + ch - 2)); ty=$((cy + ch * 4 / 10))
editor_crop="${cw}x$((ch + 30))+${cx}+${cy}"
xdotool mousemove --window "$wid" $px $py; sleep 0.5
shot "$work/hover.png"
xdotool mousedown 1
# The press selects the point (its ring turns yellow): wait for ImGui to have seen it there.
settled "$out/4_press.png" "$work/hover.png" "$editor_crop"
for step in 1 2; do xdotool mousemove --window "$wid" $px $((py + (ty - py) * step / 2)); sleep 0.2; done
settled "$out/5_drag.png" "$out/4_press.png" "$volume_crop"
xdotool mouseup 1
settled "$out/6_tf.png" "$out/4_press.png" "$volume_crop"
m0=$(mean "$out/3_zoom.png" "$volume_crop"); m1=$(mean "$out/6_tf.png" "$volume_crop")
c0=$(coverage "$out/3_zoom.png" "$volume_crop"); c1=$(coverage "$out/6_tf.png" "$volume_crop")
greater "$m1" "$(awk -v a="$m0" 'BEGIN { print a * 1.2 }')" ||
  fail "raising the opacity did not brighten the volume (mean $m0 -> $m1)"
greater "$c1" "$c0" || fail "raising the opacity did not show more of the volume ($c0 -> $c1)"
# Ctrl+Z undoes the whole drag (one step): the picture before it (the press, before the point
# moved); Ctrl+Y brings the edit back. Compared right of the panel, whose statistics change.
near() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 0.02 * b + 1e-6) }'; }
xdotool key --window "$wid" ctrl+z
settled "$out/6_undo.png" "$out/6_tf.png" "$volume_crop"
mp=$(mean "$out/4_press.png" "$picture_crop"); mu=$(mean "$out/6_undo.png" "$picture_crop")
cp_=$(coverage "$out/4_press.png" "$picture_crop"); cu=$(coverage "$out/6_undo.png" "$picture_crop")
near "$mu" "$mp" && near "$cu" "$cp_" ||
  fail "Ctrl+Z did not bring back the picture before the edit (mean $mp -> $mu, coverage $cp_ -> $cu)"
xdotool key --window "$wid" ctrl+y
settled "$out/6_redo.png" "$out/6_undo.png" "$volume_crop"
mt=$(mean "$out/6_tf.png" "$picture_crop"); mr=$(mean "$out/6_redo.png" "$picture_crop")
near "$mr" "$mt" || fail "Ctrl+Y did not redo the edit (mean $mt -> $mu -> $mr)"

log "transfer-function edit, undo and redo checked"
# Probe and double-click: with the cursor on the volume the viewer names the point it shows (a
# "probe" line with its voxel and value, also drawn over the picture); a double-click there
# makes that point the centre of the view (a "centre" line), so the picture moves.
qx=$((415 + 85)); qy=250
xdotool mousemove --window "$wid" $qx $qy; sleep 0.3
xdotool mousemove --window "$wid" $((qx + 1)) $((qy + 1))
probed() { grep -q '^probe x .* voxel .* value ' "$work/stdout"; }
poll "a probe line naming the point under the cursor" probed
shot "$work/probe.png"
xdotool click --repeat 2 --delay 80 1
centred() { grep -q '^centre ' "$work/stdout"; }
poll "the double-click's centre line" centred
settled "$out/7_centred.png" "$work/probe.png" "$volume_crop"
# M marks the point under the cursor; moved elsewhere on the volume, the probe gives the
# distance from the mark.
xdotool mousemove --window "$wid" 560 300; sleep 0.3
xdotool mousemove --window "$wid" 561 301
poll "a probe line at the centre" probed
xdotool key --window "$wid" m
marked() { grep -q '^mark ' "$work/stdout"; }
poll "the mark line" marked
xdotool mousemove --window "$wid" 600 330; sleep 0.3
xdotool mousemove --window "$wid" 601 331
measured() { grep -q '^probe x .* from the mark$' "$work/stdout"; }
poll "a probe line with the distance from the mark" measured

log "probe, double-click and mark checked"
# X switches the orientation axes (on by default, bottom right above the probe line) off.
axes_crop="110x110+985+440"
shot "$work/axes_on.png"
xdotool key --window "$wid" x
axes_off() { grep -q '^axes off$' "$work/stdout"; }
poll "the axes switched off" axes_off
settled "$out/8_axes_off.png" "$work/axes_on.png" "$axes_crop"
a0=$(coverage "$work/axes_on.png" "$axes_crop"); a1=$(coverage "$out/8_axes_off.png" "$axes_crop")
greater "$a0" "$(awk -v a="$a1" 'BEGIN { print a + 0.02 }')" ||
  fail "switching the axes off did not clear the corner (coverage $a0 -> $a1)"
log "orientation axes checked"
# F1 shows the list of keys in the middle of the window, and F1 again hides it.
keys_crop="300x200+400+200"
shot "$work/keys_before.png"
xdotool key --window "$wid" F1
keys_on() { grep -q '^keys on$' "$work/stdout"; }
poll "the keys window" keys_on
settled "$out/8_keys.png" "$work/keys_before.png" "$keys_crop"
xdotool key --window "$wid" F1
keys_off() { grep -q '^keys off$' "$work/stdout"; }
poll "the keys window closed" keys_off
log "keys window checked"
quit_window "window"

# Refinement: a heavier volume whose full-quality frame is drawn in many small steps
# (EWAVIEW_REFINE_BUDGET_MS=1: about a millisecond of GL work per UI frame). An orbit drag while
# it refines must be answered by a moving frame before the refinement finishes, and the view
# must refine again afterwards.
log "refinement: starting a second window"
: >"$work/stdout"
mkdir -p "$work/config2"  # not the first window's saved transfer function and layout
(cd "$work" && EWAVIEW_CONFIG_DIR="$work/config2" EWAVIEW_PRINT_LAYOUT=1 EWAVIEW_REFINE_BUDGET_MS=1 \
  exec "$binary" "${splatter[@]}" --synthetic marschner-lobb:64 --slab-thickness 0.5 \
  --resolution "$width,$height" >stdout 2>stderr) &
pid=$!
refining() { grep -q '^refine start' "$work/stdout"; }
poll "a full-quality frame being refined" refining
poll "the ewaview window" find_window
refining_lines() { grep -c '' "$work/stdout"; }
shot "$out/7_refining.png"
before_drag=$(refining_lines)
grep -q '^refine done' "$work/stdout" && fail "the refinement finished before the drag could start"
xdotool mousemove --window "$wid" $mx $my; sleep 0.2
drag_start=$SECONDS
xdotool mousedown 1
for step in 1 2 3 4; do xdotool mousemove --window "$wid" $((mx + 20 * step)) $my; sleep 0.1; done
xdotool mouseup 1
# The first frame drawn after the drag began must be a moving (coarse) one: the window answered
# the input without finishing the full-quality frame first.
moved() { tail -n +$((before_drag + 1)) "$work/stdout" | grep -q '^frame level [1-9]'; }
poll "a moving frame after the drag" moved
answer_s=$((SECONDS - drag_start))
first_after=$(tail -n +$((before_drag + 1)) "$work/stdout" | grep -m1 '^frame level\|^refine done')
case "$first_after" in
  "frame level "[1-9]*) ;;
  *) fail "the refinement finished ('$first_after') before the drag was answered" ;;
esac
[ "$answer_s" -le 20 ] || fail "the drag was answered only after ${answer_s}s"
# The refinement starts again once the view has held still, so by then the window has taken the
# whole drag: the first moving frame may have seen only its first 20 px (a 5-degree turn of a
# box seen face on, about 1,400 pixels changed), the picture to compare is the one after.
restarted() {
  tail -n +$((before_drag + 1)) "$work/stdout" | sed -n '/^frame level [1-9]/,$p' |
    grep -q '^refine start'
}
poll "the refinement to start again after the drag" restarted
shot "$out/8_moved.png"
moved_diff=$(differ "$out/7_refining.png" "$out/8_moved.png" "$volume_crop")
greater "$moved_diff" $((290 * 600 / 50)) ||
  fail "the orbit during refinement changed only $moved_diff pixels of the volume region"
log "refinement answered the drag in ${answer_s}s ($moved_diff px)"
quit_window "second window"

# Frames: a 4D NIfTI of two volumes, a ball and a smaller one. Page Down opens the next frame
# in place (the camera and transfer function kept), Page Up goes back round to the first.
log "frames: starting a third window on a 4D file"
python3 - "$work/frames.nii" <<'PY'
import struct, sys
n = 24
header = bytearray(352)
struct.pack_into("<i", header, 0, 348)
struct.pack_into("<8h", header, 40, 4, n, n, n, 2, 1, 1, 1)
struct.pack_into("<hh", header, 70, 2, 8)  # uint8
struct.pack_into("<8f", header, 76, 1, 1, 1, 1, 1, 1, 1, 1)
struct.pack_into("<f", header, 108, 352.0)
header[344:348] = b"n+1\0"
data = bytearray()
for radius in (9, 5):
    for z in range(n):
        for y in range(n):
            for x in range(n):
                r2 = (x - 11.5) ** 2 + (y - 11.5) ** 2 + (z - 11.5) ** 2
                data.append(200 if r2 < radius * radius else 0)
open(sys.argv[1], "wb").write(bytes(header) + bytes(data))
PY
# The panel, wider with its frame line, grows with its statistics: the ball's right half only,
# clear of the panel, the editor (x >= 714) and the probe line.
frames_crop="150x560+560+0"
start_window config3 frames.nii
settled "$out/9_frame0.png" "$black" "$frames_crop"
f0=$(coverage "$out/9_frame0.png" "$frames_crop")
page_shrinks Next "frame 1 of 2" "$out/9_frame0.png" "$out/10_frame1.png"; f1="$shrunk"
xdotool key --window "$wid" Prior
on_frame0() { grep -q "^ewaview: frame 0 of 2 in" "$work/stderr"; }
poll "frame 0 of 2 on Page Up" on_frame0
settled "$out/11_frame0_again.png" "$out/10_frame1.png" "$frames_crop"
back=$(differ "$out/9_frame0.png" "$out/11_frame0_again.png" "$frames_crop")
[ "$back" -le $((150 * 560 / 200)) ] || fail "frame 0 looks different the second time ($back px)"
log "frames paged: coverage $f0 -> $f1 -> back ($back px differ)"
quit_window "third window"

# Channels: a 4D NRRD whose first axis holds two channels: a ball of value 200, then a smaller
# one of value 40 (another stain, another range). C opens the next channel in place with its own
# transfer function (channel 0's would leave 40 all but transparent), Shift+C goes back round.
log "channels: starting a window on a two-channel NRRD"
python3 - "$work/channels.nrrd" <<'PY'
import sys
n = 24
data = bytearray()
for z in range(n):
    for y in range(n):
        for x in range(n):
            r2 = (x - 11.5) ** 2 + (y - 11.5) ** 2 + (z - 11.5) ** 2
            data += bytes([200 if r2 < 81 else 0, 40 if r2 < 25 else 0])
head = ("NRRD0004\ntype: uint8\ndimension: 4\nsizes: 2 %d %d %d\n"
        "kinds: 2-vector domain domain domain\nencoding: raw\n\n" % (n, n, n))
open(sys.argv[1], "wb").write(head.encode() + bytes(data))
PY
start_window config5 channels.nrrd
settled "$out/14_channel0.png" "$black" "$frames_crop"
k0=$(coverage "$out/14_channel0.png" "$frames_crop")
page_shrinks c "channel 1 of 2, frame 0 of 1" "$out/14_channel0.png" "$out/15_channel1.png"
k1="$shrunk"
greater "$k1" 0.02 || fail "channel 1's ball is not visible (coverage $k1): not its own transfer function?"
# The same key a second time in a row: under load its press was twice never seen by the
# viewer (no "command" line), so it is pressed again only when no command arrived at all; a
# command that arrived and did nothing still fails below.
commands_seen() { grep -c '^command ' "$work/stdout"; }
before_key=$(commands_seen)
xdotool key --window "$wid" shift+c
key_seen() { [ "$(commands_seen)" -gt "$before_key" ]; }
waited=0
until key_seen || [ $waited -ge 20 ]; do sleep 0.5; waited=$((waited + 1)); done
if ! key_seen; then
  log "Shift+C not seen by the viewer in 10 s (no command line): pressing it again"
  xdotool key --window "$wid" shift+c
fi
on_channel0() { grep -q "^ewaview: channel 0 of 2, frame 0 of 1 in" "$work/stderr"; }
poll "channel 0 of 2 on Shift+C" on_channel0
log "channels paged: coverage $k0 -> $k1"
# Ctrl+S offers the page on screen as channels-c0.nrrd beside the file; Enter saves it there
# with its transfer function, and it reads back as that channel alone.
xdotool key --window "$wid" ctrl+s; sleep 0.5
xdotool key --window "$wid" Return
saved_it() { grep -q "^ewaview: saved .*/channels-c0.nrrd (.*channels-c0.tf.json" "$work/stderr"; }
poll "the volume saved with Ctrl+S" saved_it
saved_info=$("$binary" --info "$work/channels-c0.nrrd") || fail "the saved volume does not open"
case "$saved_info" in
  *'"dims":[24,24,24]'*'"range":[0.0,200.0]'*'"channels":1'*) ;;
  *) fail "the saved volume is not channel 0: $saved_info" ;;
esac
[ -s "$work/channels-c0.tf.json" ] || fail "no transfer function beside the saved volume"
log "saved channel 0 as channels-c0.nrrd"
# A name typed over the offered one picks the format: NIfTI (gzip) here.
xdotool key --window "$wid" ctrl+s; sleep 0.5
# Typed characters reach the dialog at once, keys a frame at a time (the key trickle): type only
# once A's release is through, or under load the selection may take in the first characters.
a_ups() { grep -c '^key 65 0 \(passed\|delivered\)' "$work/stdout"; }
a_before=$(a_ups)
xdotool key --window "$wid" ctrl+a
a_done() { [ "$(a_ups)" -gt "$a_before" ]; }
poll "Ctrl+A through to the save dialog" a_done
xdotool type --window "$wid" "$work/copy.nii.gz"
xdotool key --window "$wid" Return
saved_nifti() { grep -q "^ewaview: saved .*/copy.nii.gz (" "$work/stderr"; }
poll "the volume saved as NIfTI" saved_nifti
nifti_info=$("$binary" --info "$work/copy.nii.gz") || fail "the saved NIfTI file does not open"
case "$nifti_info" in
  *'"dims":[24,24,24]'*'"range":[0.0,200.0]'*) ;;
  *) fail "the saved NIfTI file is not channel 0: $nifti_info" ;;
esac
log "saved channel 0 as copy.nii.gz"
quit_window "channels window"

# Watching: with --watch, a file rewritten (a simulation's next step) is read again in place,
# keeping the view: the ball shrinks. F5 reads it again by hand.
log "watch: starting a window on a NRRD file with --watch"
ball_nrrd() {  # ball_nrrd FILE RADIUS
  python3 - "$1" "$2" <<'PY'
import sys
n, r = 24, float(sys.argv[2])
data = bytearray(200 if (x - 11.5) ** 2 + (y - 11.5) ** 2 + (z - 11.5) ** 2 < r * r else 0
                 for z in range(n) for y in range(n) for x in range(n))
head = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: %d %d %d\nencoding: raw\n\n" % (n, n, n)
open(sys.argv[1] + ".part", "wb").write(head.encode() + bytes(data))
PY
  mv "$1.part" "$1"  # written whole, then renamed into place, as careful writers do
}
ball_nrrd "$work/ball.nrrd" 9
# Two camera bookmarks beside it, far and then near, for the tour below.
bookmark() { printf '{"name": "%s", "position": [11.5, 11.5, %s], "focal_point": [11.5, 11.5, 11.5], "view_up": [0, 1, 0], "view_angle": 30}' "$1" "$2"; }
printf '{"bookmarks": [%s, %s]}\n' "$(bookmark far 90)" "$(bookmark near 40)" >"$work/ball.bookmarks.json"
# Its settings ask for screenshots at twice the window's size, in a folder of their own.
mkdir -p "$work/config6" "$work/shots"
printf '{"capture_scale": 2, "screenshot_dir": "%s"}\n' "$work/shots" >"$work/config6/settings.json"
start_window config6 ball.nrrd --watch
settled "$out/16_watch_big.png" "$black" "$frames_crop"
ball_nrrd "$work/ball.nrrd" 5
reloads() { grep -c '^ewaview: reloaded ball.nrrd in' "$work/stderr"; }
reloaded_once() { [ "$(reloads)" -ge 1 ]; }
poll "the rewritten file to be reloaded" reloaded_once
settled "$out/17_watch_small.png" "$out/16_watch_big.png" "$frames_crop"
w0=$(coverage "$out/16_watch_big.png" "$frames_crop"); w1=$(coverage "$out/17_watch_small.png" "$frames_crop")
greater "$(awk -v a="$w0" 'BEGIN { print a * 0.6 }')" "$w1" ||
  fail "the reloaded file does not show the smaller ball (coverage $w0 -> $w1)"
[ "$(reloads)" -eq 1 ] || fail "the rewritten file was read $(reloads) times, not once"
xdotool key --window "$wid" F5
reloaded_twice() { [ "$(reloads)" -ge 2 ]; }
poll "a second reload on F5" reloaded_twice
xdotool key --window "$wid" F12
shot_saved() { grep -q '^ewaview: saved screenshot ' "$work/stderr"; }
poll "the screenshot at twice the size" shot_saved
shot_file=$(grep '^ewaview: saved screenshot ' "$work/stderr" | tail -1 | sed 's/^ewaview: saved screenshot //')
shot_size=$(identify -format '%wx%h' "$shot_file") || fail "no screenshot at $shot_file"
[ "$shot_size" = "$((2 * width))x$((2 * height))" ] ||
  fail "the screenshot is $shot_size, not twice the window ($width x $height)"
log "watched file reloaded: coverage $w0 -> $w1; F5 reloads; screenshot $shot_size"

# A resize: the view is drawn again at the new size (once the size holds) up to full quality,
# and the next screenshot is twice the new size; then back to the window's size.
shots() { grep -c '^ewaview: saved screenshot ' "$work/stderr"; }
press_until_seen() {  # press_until_seen KEY: pressed again if its command line is not seen in 5 s
  local before waited=0
  before=$(commands_seen)
  xdotool key --window "$wid" "$1"
  until [ "$(commands_seen)" -gt "$before" ] || [ $waited -ge 10 ]; do sleep 0.5; waited=$((waited + 1)); done
  if [ "$(commands_seen)" -le "$before" ]; then
    log "$1 not seen by the viewer in 5 s: pressing it again"
    xdotool key --window "$wid" "$1"
  fi
}
mark=$(wc -l <"$work/stdout")
full_since_mark() {
  [ "$(tail -n +$((mark + 1)) "$work/stdout" | grep '^frame level ' | tail -1)" = "frame level 0" ]
}
xdotool windowsize "$wid" 900 500
poll "full quality after a resize to 900x500" full_since_mark
nshots=$(shots)
press_until_seen F12
another_shot() { [ "$(shots)" -gt "$nshots" ]; }
poll "the screenshot after the resize" another_shot
shot_file=$(grep '^ewaview: saved screenshot ' "$work/stderr" | tail -1 | sed 's/^ewaview: saved screenshot //')
shot_size=$(identify -format '%wx%h' "$shot_file") || fail "no screenshot at $shot_file"
[ "$shot_size" = "1800x1000" ] || fail "the screenshot after the resize is $shot_size, not 1800x1000"
mark=$(wc -l <"$work/stdout")
xdotool windowsize "$wid" "$width" "$height"
poll "full quality at the window's size again" full_since_mark
log "resized to 900x500: full quality, screenshot $shot_size; resized back"

# Capture > Tour flies through the bookmarks (far to near) and writes 36 frames at the capture
# size into a folder of its own. The panel is scrolled until the Capture header is in view
# (the layout lines give each item's place as it moves), the header opened, Tour clicked.
place_of() { grep "^$1 " "$work/stdout" | tail -1; }
scroll_to() {  # scroll_to ITEM: the mouse wheel over the panel until ITEM lies in the window
  local start=$SECONDS x y w h
  while :; do
    [ -n "$(place_of "$1")" ] && read -r _ x y w h <<<"$(place_of "$1")" &&
      [ "$y" -ge 20 ] && [ $((y + h)) -le $((height - 2)) ] && return 0
    [ $((SECONDS - start)) -ge 60 ] && fail "could not scroll the panel to $1 ($(place_of "$1"))"
    xdotool mousemove --window "$wid" 200 300
    if [ -n "$(place_of "$1")" ] && [ "$y" -lt 20 ]; then xdotool click 4; else xdotool click 5; fi
    sleep 0.4
  done
}
click_item() {  # click_item ITEM
  local x y w h
  read -r _ x y w h <<<"$(place_of "$1")"
  xdotool mousemove --window "$wid" $((x + w / 3)) $((y + h / 2)); sleep 0.3; xdotool click 1
}
has_header() { [ -n "$(place_of capture-header)" ]; }
poll "the Capture header's layout line" has_header
# click_until ITEM DONE...: ITEM scrolled into view and clicked once it has held still (the
# panel's content above may still change height: a message expiring moves it), and again, five
# times at most, while the command DONE... has not come true within 5 s.
click_until() {
  local item="$1" held still attempt; shift
  for attempt in 1 2 3 4 5; do
    scroll_to "$item"
    held="" still=$SECONDS
    until [ "$held" = "$(place_of "$item")" ] || [ $((SECONDS - still)) -ge 20 ]; do
      held=$(place_of "$item"); sleep 0.6
    done
    scroll_to "$item"
    click_item "$item"
    for _ in $(seq 17); do "$@" && return 0; sleep 0.3; done
    log "nothing came of clicking $item at $held (try $attempt)"
  done
  return 1
}
has_tour() { [ -n "$(place_of tour-button)" ]; }
click_until capture-header has_tour ||
  fail "the Capture header did not open with the Tour button (two bookmarks loaded)"
tour_dir() { find "$work/shots" -maxdepth 1 -type d -name 'ewaview-ball-*-tour' | head -1; }
tour_started() { [ -n "$(tour_dir)" ]; }
click_until tour-button tour_started || fail "clicking Tour started no tour (no folder for its frames)"
tour_done() { [ -n "$(tour_dir)" ] && [ -f "$(tour_dir)/frame_035.png" ] && grep -q 'saved 36 frames' "$work/stderr"; }
poll "the tour's 36 frames" tour_done
[ "$(find "$(tour_dir)" -name 'frame_*.png' | wc -l)" -eq 36 ] || fail "the tour wrote $(ls "$(tour_dir)" | wc -l) files, not 36"
# Each frame is refined over UI frames, as the window's own picture is, never drawn whole in
# one (seconds on llvmpipe for a big volume, the window frozen meanwhile): one step at least
# each, the screenshot's too.
steps=$(grep -c '^capture step$' "$work/stdout")
[ "$steps" -ge 37 ] || fail "the screenshot and the tour's 36 frames took $steps capture steps, not 37 or more"
frame_size=$(identify -format '%wx%h' "$(tour_dir)/frame_000.png")
[ "$frame_size" = "$((2 * width))x$((2 * height))" ] || fail "tour frames are $frame_size, not twice the window"
all="$((2 * width))x$((2 * height))+0+0"
t0=$(coverage "$(tour_dir)/frame_000.png" "$all"); t1=$(coverage "$(tour_dir)/frame_018.png" "$all")
t2=$(coverage "$(tour_dir)/frame_035.png" "$all")
greater "$t1" "$t0" && greater "$t2" "$t1" ||
  fail "the tour does not come nearer the ball (coverage $t0, $t1, $t2 at frames 0, 18, 35)"
cp "$(tour_dir)/frame_000.png" "$out/18_tour_first.png"; cp "$(tour_dir)/frame_035.png" "$out/19_tour_last.png"
log "tour: 36 frames of $frame_size, coverage $t0 -> $t1 -> $t2"
# Capture > Turntable: 36 frames round the volume at the capture size, in a folder of its own.
turntable_dir() { find "$work/shots" -maxdepth 1 -type d -name 'ewaview-ball-*-turntable' | head -1; }
turntable_started() { [ -n "$(turntable_dir)" ]; }
click_until turntable-button turntable_started ||
  fail "clicking Turntable started no turntable (no folder for its frames)"
# A screenshot asked for while the turntable is drawn (the panel's Screenshot button, which F12
# presses too: keys sent during the turntable did not reach the window under CI's Xvfb, clicks
# do) is queued, drawn between two of its frames and written to a name of its own.
nshots=$(shots)
queued_seen() { grep -q '^ewaview: screenshot queued' "$work/stderr"; }
click_until screenshot-button queued_seen || fail "the Screenshot button during the turntable queued nothing"
turntable_done() { [ -f "$(turntable_dir)/frame_035.png" ] && [ "$(grep -c 'saved 36 frames' "$work/stderr")" -ge 2 ]; }
poll "the turntable's 36 frames" turntable_done
poll "the screenshot asked for during the turntable" another_shot
grep -q '^ewaview: screenshot queued (1 waiting)' "$work/stderr" ||
  fail "the screenshot during the turntable was not queued first in line"
queued_file=$(grep '^ewaview: saved screenshot ' "$work/stderr" | tail -1 | sed 's/^ewaview: saved screenshot //')
[ "$queued_file" != "$shot_file" ] || fail "the queued screenshot overwrote $shot_file"
queued_size=$(identify -format '%wx%h' "$queued_file") || fail "no screenshot at $queued_file"
[ "$queued_size" = "$((2 * width))x$((2 * height))" ] ||
  fail "the queued screenshot is $queued_size, not twice the window"

[ "$(find "$(turntable_dir)" -name 'frame_*.png' | wc -l)" -eq 36 ] ||
  fail "the turntable wrote $(ls "$(turntable_dir)" | wc -l) files, not 36"
frame_size=$(identify -format '%wx%h' "$(turntable_dir)/frame_018.png")
[ "$frame_size" = "$((2 * width))x$((2 * height))" ] || fail "turntable frames are $frame_size, not twice the window"
r0=$(coverage "$(turntable_dir)/frame_000.png" "$all"); r1=$(coverage "$(turntable_dir)/frame_018.png" "$all")
greater "$r0" 0.005 && greater "$r1" 0.005 || fail "the turntable's frames do not show the volume ($r0, $r1)"
cp "$(turntable_dir)/frame_018.png" "$out/20_turntable_half.png"
log "turntable: 36 frames of $frame_size, coverage $r0, $r1 at frames 0 and 18; a screenshot meanwhile queued, $queued_size"
quit_window "watch window"

# Series: a DICOM folder of two (a ball of 30 slices, a box of 20). The panel lists them;
# choosing the second in the list opens it (a box covers more of the picture than the ball).
series_note="series not checked (no fixture writer given)"
if [ -n "$fixture" ]; then
  log "series: starting a fourth window on a DICOM folder of two series"
  "$fixture" "$work/study" 2>/dev/null || fail "the fixture writer could not write the folder"
  start_window config4 study
  have_list() { grep -q '^series-list ' "$work/stdout"; }
  poll "the series list's layout line" have_list
  settled "$out/12_series_ball.png" "$black" "$frames_crop"
  s0=$(coverage "$out/12_series_ball.png" "$frames_crop")
  read -r _ lx ly lw lh < <(grep '^series-list ' "$work/stdout" | tail -1)
  xdotool mousemove --window "$wid" $((lx + lw / 3)) $((ly + lh / 2)); sleep 0.3; xdotool click 1
  have_entry() { grep -q '^series-entry 1 ' "$work/stdout"; }
  poll "the list's second entry" have_entry
  read -r _ _ ex ey ew eh < <(grep '^series-entry 1 ' "$work/stdout" | tail -1)
  xdotool mousemove --window "$wid" $((ex + ew / 3)) $((ey + eh / 2)); sleep 0.3; xdotool click 1
  opened_box() { grep -q "^ewaview: loading .*study series 1.2.826.0.1.3680043.2.1125.9" "$work/stderr"; }
  poll "the second series to load" opened_box
  settled "$out/13_series_box.png" "$out/12_series_ball.png" "$frames_crop"
  s1=$(coverage "$out/13_series_box.png" "$frames_crop")
  [ "$s0" != "$s1" ] || fail "choosing the second series did not change the picture ($s0)"
  series_note="series coverage $s0 -> $s1"
  log "$series_note"
  quit_window "fourth window"
fi

echo "PASS: idle 0 px; orbit $orbit_diff px; zoom coverage $before -> $after; copied view $view_diff px; TF mean $m0 -> $m1, coverage $c0 -> $c1, undone $mp -> $mu, redone $mt -> $mr; drag during refinement answered in ${answer_s}s ($moved_diff px); frames coverage $f0 -> $f1; channels $k0 -> $k1, saved; watched file reloaded ($w0 -> $w1), F5, screenshot $shot_size; tour $t0 -> $t2; turntable $r0, $r1; $series_note"
