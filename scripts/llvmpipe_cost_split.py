#!/usr/bin/python3
"""Where a full-quality EWA frame's time goes on software GL: renders one view headless with the
shipped shaders and with copies cut down one part at a time (loaded with --shader-dir), and
prints each variant's splat stage (kernels and slab passes) against the full one.

Usage: scripts/llvmpipe_cost_split.py [--runs N] [--binary PATH] [-- EWAVIEW ARGS]
Default view: the default volume in the default window's size (1024x768). The variants take
turns, run by run, and the minimum of N runs is kept. Their pictures are wrong by design: they
are for timing only. The variants:
  full          the shipped shaders
  no-erf        the splat fragments' depth shares without erf (a clamp in its place)
  trivial-frag  splat fragments that write zeros: rasterization, the early tests and blending
  size-1        splat points one pixel wide (trivial fragments): the per-splat cost
  vertex-only   no splat point is emitted: the vertex stage, the clears and empty slab passes
  stub-pass     slab passes that read their texel and composite it, no classification
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SPLAT_MS = re.compile(r'"splat_ms":([\d.]+)')


def edit(folder, name, old, new):
    path = os.path.join(folder, name)
    with open(path) as f:
        text = f.read()
    if old not in text:
        raise SystemExit(f"llvmpipe_cost_split: {name} no longer holds {old.strip()!r}")
    with open(path, "w") as f:
        f.write(text.replace(old, new, 1))


def trivial_fragments(folder):
    path = os.path.join(folder, "splat.frag.glsl")
    with open(path) as f:
        text = f.read()
    body = text.index("void main() {")
    with open(path, "w") as f:
        f.write(text[:body] + "void main() { outColor = vec4(0.0); outNormal = vec4(0.0); "
                "outBack = vec4(0.0); }\n")


def no_erf(folder):
    for i in range(4):
        old = f"profileErf(lo.{'xyzw'[i]}, profile)"
        edit(folder, "ewa_footprint.glsl", old, f"clamp(lo.{'xyzw'[i]}, -profile.x, profile.x)")
    edit(folder, "ewa_footprint.glsl", "float e4 = profileErf(hi, profile);",
         "float e4 = clamp(hi, -profile.x, profile.x);")


def variants(base):
    """name -> folder of shaders."""
    made = {}

    def make(name, *changes):
        folder = os.path.join(base, name)
        shutil.copytree(os.path.join(ROOT, "shaders"), folder)
        for change in changes:
            change(folder)
        made[name] = folder

    make("full")
    make("no-erf", no_erf)
    make("trivial-frag", trivial_fragments)
    make("size-1", trivial_fragments, lambda d: edit(d, "splat_point.vert.glsl",
                                                      "gl_PointSize = size;", "gl_PointSize = 1.0;"))
    make("vertex-only", lambda d: edit(d, "splat_point.vert.glsl", "  gl_PointSize = size;",
                                       "  return;"))
    make("stub-pass", lambda d: edit(d, "slab_composite.frag.glsl",
                                     "outColor = preintegratedQuarters(s, back);",
                                     "outColor = vec4(0.001 * (s.g + back.g));"))
    return made


def splat_ms(binary, shaders, args):
    out = subprocess.run([binary, os.path.join(ROOT, "assets", "default.nrrd"), "--output",
                          os.path.join(shaders, "frame.png"),
                          "--resolution", "1024,768", "--stats", "--shader-dir", shaders] + args,
                         capture_output=True, text=True, check=True)
    m = SPLAT_MS.search(out.stdout + out.stderr)
    if not m:
        raise SystemExit("llvmpipe_cost_split: no statistics from " + binary)
    return float(m.group(1))


def main(argv):
    runs, binary = 3, os.path.join(ROOT, "build", "ewaview")
    args = []
    if "--" in argv:
        args = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    while argv:
        if argv[0] == "--runs":
            runs, argv = int(argv[1]), argv[2:]
        elif argv[0] == "--binary":
            binary, argv = argv[1], argv[2:]
        else:
            raise SystemExit(__doc__)
    with tempfile.TemporaryDirectory() as base:
        made = variants(base)
        best = {name: float("inf") for name in made}
        for _ in range(runs):
            for name, folder in made.items():
                best[name] = min(best[name], splat_ms(binary, folder, args))
    full = best["full"]
    print(f"# {' '.join(['scripts/llvmpipe_cost_split.py', '--runs', str(runs)] + args)}")
    print(f"# splat stage, minimum of {runs} runs; the default volume at 1024x768")
    for name, ms in best.items():
        print(f"{name:14s} {ms:8.1f} ms  {ms / full:5.2f}x full")


if __name__ == "__main__":
    main(sys.argv[1:])
