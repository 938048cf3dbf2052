#!/usr/bin/env bash
# Runs the render tests and the benchmarks through EGL on a GPU machine from a bundle that
# scripts/gpu_bundle.sh made (no Debian packages needed there), writing logs to OUT.
# Usage: scripts/gpu_measure.sh BUNDLE DATA OUT [tests|bench|all]
#   DATA: a folder with engine/, bonsai/ and cthead/ (as ../shared/data holds them); raw files
#   may travel gzipped (NAME.raw.gz, 13 MB for the three instead of 40): unpacked here first.
#   The bundle itself travels as a .tgz under the device tool's 64 MiB (2026-12-04: 34 MB).
set -uo pipefail
bundle="$(cd "$1" && pwd)"
data="$2"
out="$3"
mode="${4:-all}"
assets="$(cd "$(dirname "$0")/../assets" && pwd)"  # the default volume and its sidecar
mkdir -p "$out"
for f in "$data"/*/*.raw.gz; do [ -e "$f" ] && gunzip -f "$f"; done
export LD_LIBRARY_PATH="$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# No libglvnd on the machine: the bundle's, pointed at NVIDIA's EGL vendor file.
if ! ldconfig -p | grep -q 'libEGL.so.1 '; then
  export LD_LIBRARY_PATH="$LD_LIBRARY_PATH:$bundle/lib/glvnd"
  vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
  [ -e "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES="$vendor"
fi
# Every program, and the render suite's own context, through EGL (OSMesa is stubbed).
export EWAVIEW_BACKEND=egl
bin="$bundle/bin"
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version --format=csv
if [ "$mode" = all ] || [ "$mode" = tests ]; then
  # The paths the tests were built with, pointing here (best effort: needs the right to make
  # them): the checkout, its ../shared/data, and the build folder with the bundle's programs.
  src="$(cat "$bundle/source_root" 2>/dev/null || true)"
  here="$(cd "$(dirname "$0")/.." && pwd)"
  if [ -n "$src" ] && [ ! -e "$src" ]; then
    mkdir -p "$(dirname "$src")" && ln -s "$here" "$src"
  fi
  if [ -n "$src" ] && [ -d "$src" ]; then
    [ -e "$src/../shared/data" ] || { mkdir -p "$src/../shared" && ln -s "$(cd "$data" && pwd)" "$src/../shared/data"; }
    build="$src/$(cat "$bundle/build_dir")"
    mkdir -p "$build/test-output"
    for b in "$bin"/*; do [ -e "$build/$(basename "$b")" ] || ln -s "$b" "$build/"; done
  fi
  "$bin/ewaview" "$data/engine/engine.nhdr" --backend egl --resolution 1024,1024 \
    -o "$out/engine_1024.png" --stats
  # The render suite (tests of OSMesa itself and of FFmpeg's videos fail: both stubbed), in 8
  # shards at once beside the unit suite: about 20 s on the H200's 16 cores.
  shards=8
  for i in $(seq 0 $((shards - 1))); do
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i "$bin/ewa_render_tests" \
      >"$out/render_tests_$i.txt" 2>&1 &
  done
  "$bin/ewa_unit_tests" >"$out/unit_tests.txt" 2>&1 &
  wait
  cat "$out"/render_tests_*.txt >"$out/render_tests.txt" && rm "$out"/render_tests_*.txt
  grep -E "^\[  (PASSED|FAILED) " "$out/render_tests.txt"
  tail -n 3 "$out/unit_tests.txt"
fi
if [ "$mode" = all ] || [ "$mode" = bench ]; then
  # The default frame, rasterized (ewa_ms) and in compute tiles from the GPU partition's lists
  # (tile_ewa_ms, post-classified: the H200 took 8.2/4.6/11.5 ms at 1024^2 on 2026-11-28) with
  # their pictures; then shaded (ray normals, the default, and the field's).
  "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --repeats 20 \
    --images "$out/images_default" | tee "$out/compare.txt"
  for normals in ray field; do
    "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --sizes 1024 --repeats 7 \
      --shading --post-normals "$normals" | tee -a "$out/compare.txt"
  done
  # The compute tiles (tiles_ms) at 8 x 8 pixels beside the default 16 x 16 above.
  "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --sizes 1024 --repeats 7 \
    --tile-size 8 | tee -a "$out/compare.txt"
  # Auto passes a slab (above) against one pass always (the H200: 0.57-0.64x for engine and
  # CThead at 1024^2).
  "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --sizes 1024 --repeats 7 \
    --slab-passes 1 | tee -a "$out/compare.txt"
  # Post- against pre-classified (the crisp-pictures issue allows 1.3x; rasterized the H100 gave
  # 2.07-2.42x on 2026-11-28, in tiles the H200 1.21-1.49x); the pre-classified run also times the compute EWA splatter
  # (tile_ewa_ms: 0.094-0.11x the rasterized frame there) and writes both pictures to
  # OUT/images (within 3 levels of each other on the H200). Then two samples a slab in slabs
  # 1 voxel thick: the same half-voxel spacing of values with one slab image instead of two (on
  # llvmpipe as near to VTK's ray caster as the default), for 1.33x the slab entries and twice
  # the slab passes (the H200: 0.79x the default frame for engine and CThead, 0.96x bonsai).
  "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --sizes 1024 --repeats 7 \
    --classification pre --images "$out/images" | tee -a "$out/compare.txt"
  "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --sizes 1024 --repeats 7 \
    --slab-samples 2 --slab-thickness 1 | tee -a "$out/compare.txt"
  # Two samples in slabs 1.5 voxels thick: 1.11x the default's slab entries (the default volume
  # at 1024x768), one image; on llvmpipe 0.92-0.94x the default's splat stage, but against VTK's
  # rays engine's and CThead's worst views 0.970 and 0.969 (the default's 0.975 and 0.976):
  # what the second image costs on a GPU, not a default.
  "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --sizes 1024 --repeats 7 \
    --slab-samples 2 --slab-thickness 1.5 | tee -a "$out/compare.txt"
  # Bytes a splat with each partition (the GPU's by default there), and a 512^3 volume.
  "$bin/ewaview-compare" --backend egl --no-vtk --data "$data" --volumes engine --sizes 1024 \
    --repeats 3 --partition cpu | tee -a "$out/compare.txt"
  "$bin/ewaview" --synthetic marschner-lobb:512 --backend egl --resolution 1024,1024 \
    -o "$out/ml512.png" --stats | tee "$out/ml512.txt"
  # Coarser slab images: the default volume in the window's size (kernels 3.3 pixels wide:
  # scales 1.25-1.75) with them and without, three times each (the H200: 0.66x the splat stage).
  for i in 1 2 3; do
    for res in auto full; do
      echo "default volume 1024x768 --slab-resolution $res: $("$bin/ewaview" "$assets/default.nrrd" \
        --backend egl --resolution 1024,768 -o "$out/default_$res.png" --stats --slab-resolution "$res")"
    done
  done | tee "$out/coarse_slabs.txt"
  # Whole frames in compute tiles (--splatter tiles) against rasterized, taking turns.
  for i in 1 2 3; do
    for splatter in raster tiles; do
      echo "default volume 1024x768 --splatter $splatter: $("$bin/ewaview" "$assets/default.nrrd" \
        --backend egl --resolution 1024,768 -o "$out/default_$splatter.png" --stats \
        --splatter "$splatter")"
    done
  done | tee "$out/splatter.txt"
  # Classification on one thread beside all the machine's cores (the CPU side of a new volume
  # or transfer function): the three volumes, then a 512^3 one once each way.
  "$bin/ewaview-classify-bench" "$data/engine/engine.nhdr" "$data/bonsai/bonsai.nhdr" \
    "$data/cthead/CThead.nhdr" | tee "$out/classify.txt"
  "$bin/ewaview-classify-bench" --synthetic marschner-lobb:512 --repeats 1 | tee -a "$out/classify.txt"
  # The window's refinement, headless (no display there): the default volume, engine, CThead.
  "$bin/ewaview-interact-bench" --backend egl --size 1024 "$assets/default.nrrd" \
    "$data/engine/engine.nhdr" "$data/cthead/CThead.nhdr" | tee "$out/interact.txt"
fi
