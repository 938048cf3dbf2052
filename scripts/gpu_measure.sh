#!/usr/bin/env bash
# Runs the render tests and the benchmarks through EGL on a GPU machine from a bundle that
# scripts/gpu_bundle.sh made (no Debian packages needed there), writing logs to OUT.
# Usage: scripts/gpu_measure.sh BUNDLE DATA OUT [tests|bench|all]
#   DATA: a folder with engine/, bonsai/ and cthead/ (as ../shared/data holds them)
set -uo pipefail
bundle="$(cd "$1" && pwd)"
data="$2"
out="$3"
mode="${4:-all}"
assets="$(cd "$(dirname "$0")/../assets" && pwd)"  # the default volume and its sidecar
mkdir -p "$out"
export LD_LIBRARY_PATH="$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# Every program, and the render suite's own context, through EGL (OSMesa is stubbed).
export EWAVIEW_BACKEND=egl
bin="$bundle/bin"
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version --format=csv
if [ "$mode" = all ] || [ "$mode" = tests ]; then
  "$bin/ewaview" "$data/engine/engine.nhdr" --backend egl --resolution 1024,1024 \
    -o "$out/engine_1024.png" --stats
  # The render suite (tests of OSMesa itself and of FFmpeg's videos fail: both stubbed).
  "$bin/ewa_render_tests" >"$out/render_tests.txt" 2>&1
  grep -E "^\[  (PASSED|FAILED) " "$out/render_tests.txt"
  "$bin/ewa_unit_tests" >"$out/unit_tests.txt" 2>&1
  tail -n 3 "$out/unit_tests.txt"
fi
if [ "$mode" = all ] || [ "$mode" = bench ]; then
  "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --repeats 20 | tee "$out/compare.txt"
  "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --repeats 20 \
    --occlusion-culling off | tee -a "$out/compare.txt"
  # Bytes a splat with each partition (the GPU's by default there), and a 512^3 volume.
  "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --volumes engine --sizes 1024 \
    --repeats 3 --partition cpu | tee -a "$out/compare.txt"
  "$bin/ewaview" --synthetic marschner-lobb:512 --backend egl --resolution 1024,1024 \
    -o "$out/ml512.png" --stats | tee "$out/ml512.txt"
  # Coarser slab images (measured on llvmpipe only): the default volume in the window's size
  # (kernels 3.3 pixels wide: scales 1.25-1.75) with them and without, three times each.
  for i in 1 2 3; do
    for res in auto full; do
      echo "default volume 1024x768 --slab-resolution $res: $("$bin/ewaview" "$assets/default.nrrd" \
        --backend egl --resolution 1024,768 -o "$out/default_$res.png" --stats --slab-resolution "$res")"
    done
  done | tee "$out/coarse_slabs.txt"
fi
