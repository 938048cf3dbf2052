// A compute tile splatter for the benchmarks, in four passes chosen by a define: COUNT_PASS
// (footprints per screen tile), SCAN_PASS (each tile's first entry), SCATTER_PASS (the tile
// lists) and ACCUMULATE_PASS (one work group a tile adds up its footprints per pixel and
// stores two images, as a slab with four samples has): no rasterizer, no blending.
#include "ewa_footprint.glsl"
#include "tile_range.glsl"
#include "dispatch_index.glsl"

// Per footprint two vec4: (centre x, centre y, half width, half height) in pixels (y up, pixel
// centres at +0.5), then (conic xx, conic xy, conic yy, peak).
layout(std430, binding = 0) readonly buffer Footprints { vec4 footprints[]; };
layout(std430, binding = 1) buffer Cursor { uint cursor[]; };    // counts, then next free entry
layout(std430, binding = 2) buffer Offsets { uint offsets[]; };  // tiles + 1 first entries
layout(std430, binding = 3) buffer Entries { uint entries[]; };  // footprint per entry

uniform uint uCount;     // footprints
uniform ivec2 uTiles;    // tiles across and up
uniform ivec2 uViewport; // pixels
uniform float uCutoff;

const int kTile = TILE_SIZE;

#if defined(COUNT_PASS) || defined(SCATTER_PASS)
layout(local_size_x = 256) in;

void main() {
  uint i = dispatchIndex(256u);
  if (i >= uCount) return;
  vec4 box = footprints[2u * i];
  ivec2 t0, t1;
  if (!boxTiles(box, uViewport, kTile, t0, t1)) return;
  for (int y = t0.y; y <= t1.y; ++y) {
    for (int x = t0.x; x <= t1.x; ++x) {
      uint tile = uint(y * uTiles.x + x);
#ifdef COUNT_PASS
      atomicAdd(cursor[tile], 1u);
#else
      entries[atomicAdd(cursor[tile], 1u)] = i;
#endif
    }
  }
}
#endif

#ifdef SCAN_PASS
// One group: each invocation sums a run of tiles, the runs' sums are scanned in shared memory,
// and each run then writes its tiles' first entries (and the scatter's cursors).
layout(local_size_x = 1024) in;
shared uint runSums[1024];

void main() {
  uint tiles = uint(uTiles.x * uTiles.y);
  uint run = (tiles + 1023u) / 1024u;
  uint first = gl_LocalInvocationID.x * run;
  uint last = min(first + run, tiles);
  uint sum = 0u;
  for (uint t = first; t < last; ++t) sum += cursor[t];
  runSums[gl_LocalInvocationID.x] = sum;
  barrier();
  for (uint step = 1u; step < 1024u; step *= 2u) {
    uint add = gl_LocalInvocationID.x >= step ? runSums[gl_LocalInvocationID.x - step] : 0u;
    barrier();
    runSums[gl_LocalInvocationID.x] += add;
    barrier();
  }
  uint next = runSums[gl_LocalInvocationID.x] - sum;  // exclusive
  for (uint t = first; t < last; ++t) {
    uint count = cursor[t];
    offsets[t] = next;
    cursor[t] = next;
    next += count;
  }
  if (gl_LocalInvocationID.x == 1023u) offsets[tiles] = runSums[1023];
}
#endif

#ifdef ACCUMULATE_PASS
layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;
layout(IMAGE_FORMAT, binding = 0) uniform writeonly image2D uFront;
layout(IMAGE_FORMAT, binding = 1) uniform writeonly image2D uBack;
const uint kBatch = uint(TILE_SIZE * TILE_SIZE);
shared vec4 batchBox[kBatch];
shared vec4 batchConic[kBatch];

// Adds batch footprint j (none past n) at the pixel centred at `centre` to the two images' sums.
void addFootprint(uint j, uint n, vec2 centre, inout vec4 front, inout vec4 back) {
  if (j >= n) return;
  vec4 box = batchBox[j];
  vec2 dx = centre - box.xy;
  // Outside the footprint's box: skipped, by whole SIMD rows of pixels where all miss.
  if (any(greaterThan(abs(dx), box.zw))) return;
  vec4 q = batchConic[j];
  float r = q.x * dx.x * dx.x + 2.0 * q.y * dx.x * dx.y + q.z * dx.y * dx.y;
  float w = q.w * windowedGaussian(r, uCutoff);
  // Stand-ins for a slab's four (weight * value, weight) pairs.
  front += vec4(0.5 * w, w, 0.25 * w, w);
  back += vec4(0.125 * w, w, 0.0625 * w, w);
}

void main() {
  uint tile = gl_WorkGroupID.y * uint(uTiles.x) + gl_WorkGroupID.x;
  uint begin = offsets[tile], end = offsets[tile + 1u];
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  vec2 centre = vec2(pixel) + 0.5;
  vec4 front = vec4(0.0), back = vec4(0.0);
  for (uint base = begin; base < end; base += kBatch) {
    // The group loads a batch of its tile's footprints once; every pixel reads them all.
    uint k = base + gl_LocalInvocationIndex;
    if (k < end) {
      uint f = entries[k];
      batchBox[gl_LocalInvocationIndex] = footprints[2u * f];
      batchConic[gl_LocalInvocationIndex] = footprints[2u * f + 1u];
    }
    barrier();
    uint n = min(kBatch, end - base);
    // Eight footprints an iteration: llvmpipe ends a shader's loops after 65535 iterations in
    // all (LP_MAX_TGSI_LOOP_ITERATIONS), which a busy tile reaches one footprint at a time.
    for (uint j = 0u; j < n; j += 8u) {
      for (uint u = 0u; u < 8u; ++u) addFootprint(j + u, n, centre, front, back);
    }
    barrier();
  }
  if (all(lessThan(pixel, uViewport))) {
    imageStore(uFront, pixel, front);
    imageStore(uBack, pixel, back);
  }
}
#endif
