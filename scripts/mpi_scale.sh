#!/usr/bin/env bash
# Scale check for ewaview-mpi, not part of the test suite: writes a raw volume larger than one
# rank's address-space limit (prlimit --as), renders it on RANKS ranks each under that limit,
# and prints each rank's brick, render time, voxels read and peak memory, the composite time and
# the bytes each rank hands to the composite (and sends in it, where --stats has bytes_sent).
# The time against rank count on a volume every rank holds is bench/mpi_scale_bench.py.
# Usage: scripts/mpi_scale.sh [BUILD_DIR]
#   env: DIMS=X,Y,Z (1024,1024,1152 uint8)  RANKS (8)  LIMIT_MB (per rank, 1024)  OUT (folder)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
dims=${DIMS:-1024,1024,1152}
ranks=${RANKS:-8}
limit_mb=${LIMIT_MB:-1024}
out=${OUT:-/tmp/ewa_mpi_scale}
mkdir -p "$out"
IFS=, read -r nx ny nz <<<"$dims"
bytes=$((nx * ny * nz))
if ((bytes <= limit_mb * 1024 * 1024)); then
  echo "mpi_scale: the volume ($bytes bytes) must exceed one rank's limit ($limit_mb MiB)" >&2
  exit 2
fi
raw="$out/blobs_${nx}x${ny}x${nz}.raw"
if [[ ! -f $raw || $(stat -c %s "$raw") -ne $bytes ]]; then
  echo "mpi_scale: writing $raw ($((bytes / 1048576)) MiB)" >&2
  # Slab by slab, so the writer itself stays small: a few soft balls in an empty box, so that
  # most voxels are transparent as in sparse data (cells, vessels, particles).
  /usr/bin/python3 - "$raw" "$nx" "$ny" "$nz" <<'PY'
import sys
import numpy as np
path, nx, ny, nz = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
rng = np.random.default_rng(7)
balls = [(rng.uniform(0.2, 0.8) * nx, rng.uniform(0.2, 0.8) * ny, rng.uniform(0.2, 0.8) * nz,
          rng.uniform(0.03, 0.06) * min(nx, ny, nz)) for _ in range(8)]
y, x = np.meshgrid(np.arange(ny, dtype=np.float32), np.arange(nx, dtype=np.float32), indexing='ij')
with open(path, 'wb') as f:
    for k in range(nz):
        v = np.zeros((ny, nx), np.float32)
        for cx, cy, cz, r in balls:
            d2 = ((x - cx) ** 2 + (y - cy) ** 2 + (k - cz) ** 2) / (r * r)
            v = np.maximum(v, 255.0 * np.clip(1.2 - d2, 0.0, 1.0))
        f.write(v.astype(np.uint8).tobytes())
PY
fi
echo "mpi_scale: $ranks ranks, each under prlimit --as ${limit_mb} MiB, volume $((bytes / 1048576)) MiB" >&2
# Few malloc arenas: glibc reserves 64 MiB of address space for each thread's arena, which
# prlimit --as counts though little of it is used.
mpirun --allow-run-as-root --oversubscribe -x MALLOC_ARENA_MAX=2 -np "$ranks" \
  prlimit --as=$((limit_mb * 1024 * 1024)) -- "$build/ewaview-mpi" "$raw" --raw-dims "$dims" \
  --raw-type uint8 --resolution 512,512 --termination 1 --output "$out/scale.png" --stats \
  >"$out/stats.json"
python3 - "$out/stats.json" <<'PY'
import json, sys
s = json.loads(open(sys.argv[1]).read().strip().splitlines()[-1])
print(f"ranks {s['ranks']}, picture {s['width']}x{s['height']}, ghost {s['ghost']}, "
      f"composite {s['composite_ms']:.1f} ms, {s['picture_bytes']} bytes a rank")
print(f"{'rank':>4} {'brick low':>18} {'brick high':>18} {'render ms':>10} {'voxels read':>12} "
      f"{'peak MiB':>9} {'bytes sent':>11}")
for b in s['bricks']:
    sent = b.get('bytes_sent', 'n/a')  # where --stats has it
    print(f"{b['rank']:>4} {str(b['low']):>18} {str(b['high']):>18} {b['render_ms']:>10.1f} "
          f"{b['voxels_read']:>12} {b['peak_rss_mb']:>9.1f} {sent:>11}")
PY
echo "mpi_scale: picture in $out/scale.png" >&2
