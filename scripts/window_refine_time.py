#!/usr/bin/python3
"""Time to full quality in the window: opens ewaview under Xvfb with EWAVIEW_FRAME_LOG=1 and a
scratch settings folder, and measures from its first UI frame to the first full-quality frame
after the progressive refinement, with the refinement's UI frames and steps, and the worst UI
frame between the first picture and the refinement (the full level's splats arriving from the
worker, the coarse levels warming up).

Usage: scripts/window_refine_time.py [--runs N] BINARY [BINARY ...] [-- EWAVIEW ARGS]
Several binaries (a build before a change and after it) take turns, run by run, so a machine
that slows down hits them alike. Needs xvfb-run; the window is the default 1024x768.
"""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

FRAME = re.compile(r'frame ([\d.]+) ms, (refining|level (\d+))')
STEP = re.compile(r'step ([\d.]+)')


def measure(binary, args, timeout=180.0):
    """(seconds to full quality, refining UI frames, seconds of steps, worst refining frame ms,
    refining frames over 100 ms, worst frame ms between the first picture and the refinement),
    the finishing frame counted with the refining ones."""
    env = dict(os.environ, EWAVIEW_FRAME_LOG='1', EWAVIEW_CONFIG_DIR=tempfile.mkdtemp())
    proc = subprocess.Popen(['xvfb-run', '-a', '-s', '-screen 0 1280x1024x24', binary] + args,
                            stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, env=env, text=True,
                            start_new_session=True)
    first = done = None
    frames, steps, worst, over = 0, 0.0, 0.0, 0
    pictured, waiting = False, 0.0  # the first picture drawn; the worst frame after it, before
    deadline = time.time() + timeout
    try:
        for line in proc.stderr:
            m = FRAME.search(line)
            if not m:
                continue
            now = time.time()
            first = first or now
            ms = float(m.group(1))
            if frames == 0 and pictured and m.group(2) != 'refining':
                waiting = max(waiting, ms)
            pictured = pictured or '(render' in line
            if m.group(2) == 'refining':
                frames += 1
                worst = max(worst, ms)
                over += ms > 100.0
                steps += float(STEP.search(line).group(1))
            elif frames > 0 and m.group(3) == '0':
                done = now
                worst = max(worst, ms)  # the frame that shows the finished picture
                over += ms > 100.0
                break
            if now > deadline:
                break
    finally:
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait()
    if done is None:
        raise SystemExit(f'{binary}: no full-quality frame after a refinement within {timeout} s')
    return done - first, frames, steps / 1000.0, worst, over, waiting


def main(argv):
    runs = 1
    if argv[:1] in (['-h'], ['--help']):
        print(__doc__.strip())
        return
    if argv[:1] == ['--runs']:
        runs, argv = int(argv[1]), argv[2:]
    binaries, args = (argv[:argv.index('--')], argv[argv.index('--') + 1:]) if '--' in argv \
        else (argv, [])
    if not binaries:
        raise SystemExit(__doc__)
    for _ in range(runs):
        for b in binaries:
            wall, frames, steps, worst, over, waiting = measure(b, args)
            print(f'{b}: full quality after {wall:.2f} s, {frames} refining UI frames, '
                  f'steps {steps:.2f} s, worst refining frame {worst:.0f} ms, '
                  f'{over} over 100 ms, worst frame before it {waiting:.0f} ms', flush=True)


if __name__ == '__main__':
    main(sys.argv[1:])
