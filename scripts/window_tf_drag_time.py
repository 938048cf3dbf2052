#!/usr/bin/python3
"""UI frames while a transfer-function point is dragged: opens ewaview on an X display with
EWAVIEW_FRAME_LOG=1, EWAVIEW_PRINT_LAYOUT=1 and a scratch settings folder, waits for the first
full-quality picture, then drags the opacity point at the middle of the editor's plot up in
STEPS moves 0.3 s apart (each an edit: the coarse level classifies again and builds its
pre-integration table, a worker builds the full level's splats) and reports the UI frames from
the press until full quality is refined again.

Usage: xvfb-run -a -s "-screen 0 1280x1024x24" scripts/window_tf_drag_time.py [--runs N]
       [--steps STEPS] [--verbose] [--orbit] [--screenshot] [--capture-scale N] [--resize W,H]
       BINARY [BINARY ...] [-- EWAVIEW ARGS]
--verbose prints the log line of every frame that drew a level whole (render, classify,
partition, splat and final ms). --orbit drags the view across the volume instead (STEPS moves
of 15 pixels 0.1 s apart, 20 by default), timing the moving frames of an orbit the same way.
--screenshot presses F12 on the release (a coarse picture on screen) and waits for the file too;
--capture-scale N makes screenshots N times the window's size (the panel's "size"). --resize
W,H resizes the window to W x H instead of any drag (the screen must hold it: xvfb-run -s
"-screen 0 2560x1440x24"), and times the UI frames from the resize to full quality; with
--screenshot, F12 is pressed once the window's full picture is back, so the capture at a size
larger than the window is timed instead.
Several binaries (a build before a change and after it) take turns, run by run, so a machine
that slows down hits them alike. Needs xdotool and a display (DISPLAY set).
"""
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import threading
import time

FRAME = re.compile(r'^ewaview: frame ([\d.]+) ms, (refining|level \d+)')
DONE = re.compile(r'^ewaview: full quality in ')


class Lines:
    """A pipe's lines, read on a thread as they come."""

    def __init__(self, pipe):
        self.lines = []
        self.lock = threading.Lock()
        self.thread = threading.Thread(target=self._read, args=(pipe,), daemon=True)
        self.thread.start()

    def _read(self, pipe):
        for line in pipe:
            with self.lock:
                self.lines.append(line.rstrip('\n'))

    def snapshot(self):
        with self.lock:
            return list(self.lines)


def wait_for(what, test, timeout):
    deadline = time.time() + timeout
    while time.time() < deadline:
        found = test()
        if found:
            return found
        time.sleep(0.1)
    raise SystemExit(f'no {what} within {timeout} s')


def xdotool(*args, check=True):
    return subprocess.run(['xdotool'] + [str(a) for a in args], check=check, text=True,
                          capture_output=True).stdout


def measure(binary, args, steps, verbose=False, orbit=False, screenshot=False, timeout=180.0,
            capture_scale=1, resize=None):
    """(frames from the press to full quality again, worst of them ms, worst frame that drew a
    coarse level ms, frames over 100 ms, seconds from the release to full quality)."""
    config = tempfile.mkdtemp()
    with open(os.path.join(config, 'settings.json'), 'w') as f:  # screenshots beside it
        json.dump({'screenshot_dir': config, 'capture_scale': capture_scale}, f)
    env = dict(os.environ, EWAVIEW_FRAME_LOG='1', EWAVIEW_PRINT_LAYOUT='1',
               EWAVIEW_CONFIG_DIR=config)
    proc = subprocess.Popen([binary] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env=env, text=True, start_new_session=True)
    out, err = Lines(proc.stdout), Lines(proc.stderr)

    def seen(test, since):
        return lambda: any(test(l) for l in err.snapshot()[since:])

    def saved(line):
        return line.startswith('ewaview: saved screenshot ')
    try:
        wait_for('first full-quality picture', seen(DONE.match, 0), timeout)
        # Not found yet: xdotool search exits 1 and prints nothing; ask again.
        wid = wait_for('ewaview window', lambda: xdotool(
            'search', '--onlyvisible', '--pid', proc.pid, '--name', '^ewaview$',
            check=False).split(), 10)[0]
        if resize:
            mark = len(err.snapshot())
            xdotool('windowsize', wid, *resize)
            released = time.time()
            wait_for('full quality after the resize', seen(DONE.match, mark), timeout)
            if screenshot:  # then F12, and the capture alone is timed
                mark = len(err.snapshot())
                xdotool('key', '--window', wid, 'F12')
                released = time.time()
                wait_for('the screenshot', seen(saved, mark), timeout)
        else:
            if orbit:
                # Across the volume in the default 1024x768 window (the window test's orbit),
                # 15 pixels a move, 0.1 s apart.
                px, py = 560, 300
                moves = [(px + 15 * step, py) for step in range(1, steps + 1)]
                pause = 0.1
            else:
                canvas = [l for l in out.snapshot() if l.startswith('tf-canvas ')][-1]
                cx, cy, cw, ch = (int(float(v)) for v in canvas.split()[1:5])
                # The opacity point at the plot's middle value, alpha 0 (the default
                # function's), up to 0.6 of the plot's height.
                px, py, ty = cx + cw // 2, cy + ch - 2, cy + ch * 4 // 10
                moves = [(px, py + (ty - py) * step // steps) for step in range(1, steps + 1)]
                pause = 0.3
            xdotool('mousemove', '--window', wid, px, py)
            time.sleep(0.5)
            mark = len(err.snapshot())
            xdotool('mousedown', 1)
            time.sleep(0.5)
            for x, y in moves:
                xdotool('mousemove', '--window', wid, x, y)
                time.sleep(pause)
            xdotool('mouseup', 1)
            released = time.time()
            if screenshot:
                xdotool('key', '--window', wid, 'F12')
                wait_for('the screenshot', seen(saved, mark), timeout)

            def full_quality():
                lines = err.snapshot()[mark:]
                if any(DONE.match(l) for l in lines):
                    return True
                # A screenshot drawn whole leaves full quality on screen with no refinement.
                frames = [m.group(2) for m in map(FRAME.match, lines) if m]
                return screenshot and frames[-1:] == ['level 0']
            wait_for('full quality after the drag', full_quality, timeout)
        refined = time.time()
    finally:
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait()
    lines = err.snapshot()[mark:]
    if verbose:  # the frames that drew a level whole, with where their time went
        for line in lines:
            if ' (render ' in line:
                print('  ' + line, flush=True)
    frames = [FRAME.match(l) for l in lines]
    frames = [(float(m.group(1)), m.group(2)) for m in frames if m]
    worst = max(ms for ms, _ in frames)
    coarse = max((ms for ms, kind in frames if kind != 'refining'), default=0.0)
    over = sum(ms > 100.0 for ms, _ in frames)
    return len(frames), worst, coarse, over, refined - released


def main(argv):
    runs, steps, verbose, orbit, screenshot = 1, None, False, False, False
    capture_scale, resize = 1, None
    if argv[:1] in (['-h'], ['--help']):
        print(__doc__.strip())
        return
    while argv[:1] in (['--runs'], ['--steps'], ['--verbose'], ['--orbit'], ['--screenshot'],
                       ['--capture-scale'], ['--resize']):
        if argv[0] in ('--verbose', '--orbit', '--screenshot'):
            verbose = verbose or argv[0] == '--verbose'
            orbit = orbit or argv[0] == '--orbit'
            screenshot = screenshot or argv[0] == '--screenshot'
            argv = argv[1:]
            continue
        if argv[0] == '--runs':
            runs = int(argv[1])
        elif argv[0] == '--capture-scale':
            capture_scale = int(argv[1])
        elif argv[0] == '--resize':
            resize = [int(v) for v in argv[1].split(',')]
        else:
            steps = int(argv[1])
        argv = argv[2:]
    binaries, args = (argv[:argv.index('--')], argv[argv.index('--') + 1:]) if '--' in argv \
        else (argv, [])
    if not binaries or not os.environ.get('DISPLAY'):
        raise SystemExit(__doc__)
    steps = steps or (20 if orbit else 4)
    for _ in range(runs):
        for b in binaries:
            frames, worst, coarse, over, wall = measure(b, args, steps, verbose, orbit, screenshot,
                                                        capture_scale=capture_scale, resize=resize)
            start = 'the resize' if resize and not screenshot else \
                'F12' if resize else 'the press'
            end = 'the file' if screenshot and resize else 'full quality'
            print(f'{b}: {frames} UI frames from {start} to {end}, worst {worst:.0f} ms '
                  f'(coarse {coarse:.0f} ms), {over} over 100 ms; {end} {wall:.2f} s '
                  f'after {"the release" if not resize else start}', flush=True)


if __name__ == '__main__':
    main(sys.argv[1:])
