// A compute EWA splatter for the benchmarks (front to back), in passes chosen
// by a define: COUNT_PASS (slab entries per screen tile and slab), SCATTER_PASS (the lists,
// each tile's slab by slab; the scan between them is tile_splat.comp.glsl's) and
// COMPOSITE_PASS (pre-classified; one work group a tile: each slab's footprints added up per
// pixel with their exact depth share, the slab composited, the tile left once every pixel is
// opaque; post-classified frames composite in tile_ewa_post.comp.glsl): no rasterizer, no
// blending, no slab images.
#include "ewa_footprint.glsl"
#include "clip_region.glsl"
#include "tile_range.glsl"
#include "dispatch_index.glsl"

// Per splat four vec4: (centre x, centre y, half width, half height) in pixels (y up, pixel
// centres at +0.5); (conic xx, conic xy, conic yy, optical depth at the centre); (camera depth
// of the kernel's centre, its slope per pixel x and y, its depth sigma); (colour rgb, unused).
layout(std430, binding = 0) readonly buffer Splats { vec4 splats[]; };
layout(std430, binding = 1) buffer Cursor { uint cursor[]; };    // counts, then next free entry
layout(std430, binding = 2) buffer Offsets { uint offsets[]; };  // buckets + 1 first entries
layout(std430, binding = 4) buffer Lists { uint lists[]; };   // splat | flags per bucket entry
layout(std430, binding = 5) readonly buffer Slabs { vec2 slabDepths[]; };  // near, far

const uint kFirstSlab = 1u << 31;  // src/core/slab_partition.h
const uint kLastSlab = 1u << 30;
const uint kIndexMask = kLastSlab - 1u;

uniform uint uCount;      // slab entries
uniform uint uSlabCount;  // slabs; bucket (tile, slab) is tile * uSlabCount + slab
uniform ivec2 uTiles;     // tiles across and up
uniform ivec2 uViewport;  // pixels
uniform float uCutoff;
uniform vec2 uDepthProfile;  // DepthProfile, as the splat fragments take it
uniform float uTermination;  // a pixel stops at this opacity
// Pixels the lists reach beyond each tile's own: 1 for the post-classified composite
// (tile_ewa_post.comp.glsl), whose normals take the neighbouring pixels' values.
uniform float uBorder;

const int kTile = TILE_SIZE;

#ifdef GPU_ORDER
// The GPU partition's lists (GpuSlabPartition): its order list, slab by slab, and each slab's
// first entry.
layout(std430, binding = 3) readonly buffer Order { uint order[]; };
layout(std430, binding = 6) readonly buffer SlabFirst { uint slabFirst[]; };

// Entry e as (splat | kFirstSlab | kLastSlab, slab): its slab is the last whose first entry is
// at most e (an empty slab's first entry is the next slab's).
uvec2 entryAt(uint e) {
  uint lo = 0u, hi = uSlabCount - 1u;
  while (lo < hi) {
    uint mid = (lo + hi + 1u) / 2u;
    if (slabFirst[mid] <= e) lo = mid; else hi = mid - 1u;
  }
  return uvec2(order[e], lo);
}
#else
// The slab entries in slab order: (splat | kFirstSlab | kLastSlab, slab).
layout(std430, binding = 3) readonly buffer Entries { uvec2 entries[]; };

uvec2 entryAt(uint e) { return entries[e]; }
#endif

#if defined(COUNT_PASS) || defined(SCATTER_PASS)
layout(local_size_x = 256) in;

void main() {
  uint e = dispatchIndex(256u);
  if (e >= uCount) return;
  uvec2 entry = entryAt(e);
  vec4 box = splats[4u * (entry.x & kIndexMask)];
  ivec2 t0, t1;
  if (!boxTiles(box + vec4(0.0, 0.0, uBorder, uBorder), uViewport, kTile, t0, t1)) return;
  for (int y = t0.y; y <= t1.y; ++y) {
    for (int x = t0.x; x <= t1.x; ++x) {
      uint bucket = uint(y * uTiles.x + x) * uSlabCount + entry.y;
#ifdef COUNT_PASS
      atomicAdd(cursor[bucket], 1u);
#else
      lists[atomicAdd(cursor[bucket], 1u)] = entry.x;
#endif
    }
  }
}
#endif

#ifdef COMPOSITE_PASS
layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;
// Premultiplied, front to back; a draw in chunks of slabs carries it from one to the next.
layout(rgba32f, binding = 0) uniform image2D uPicture;
uniform uint uSlabBegin;  // this dispatch's slabs: [uSlabBegin, uSlabEnd)
uniform uint uSlabEnd;
const uint kBatch = uint(TILE_SIZE * TILE_SIZE);
#include "tile_batch.glsl"

// (colour * optical depth, optical depth) of batch splat j (none past n) at the pixel centred at
// `centre`, in the slab between `depths`: its footprint and its share of the kernel along the
// ray (clipped: inside the depths `kept`), as the splat fragments take them.
vec4 splatAt(uint j, uint n, vec2 centre, vec2 depths, vec2 kept) {
  vec2 dx;
  float r;
  if (!batchFootprint(j, n, centre, dx, r)) return vec4(0.0);
  vec4 q = batch[4u * j + 1u];
  vec4 z = batch[4u * j + 2u];
  uint flags = batchOpen[j];
  bool openNear = (flags & kFirstSlab) != 0u, openFar = (flags & kLastSlab) != 0u;
  float mu = z.x + dot(z.yz, dx);
  float share =
      uClipCount > 0
          ? clippedSlabFraction(mu, z.w, depths.x, depths.y, openNear, openFar, kept,
                                uDepthProfile)
          : slabFraction(mu, z.w, depths.x, depths.y, openNear, openFar, uDepthProfile);
  float depth = q.w * windowedGaussian(r, uCutoff) * share;
  return vec4(batch[4u * j + 3u].rgb * depth, depth);
}

void main() {
  uint tile = gl_WorkGroupID.y * uint(uTiles.x) + gl_WorkGroupID.x;
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  vec2 centre = vec2(pixel) + 0.5;
  vec2 kept = clippedDepths(centre);  // the crop box and clipping planes along this ray
  bool inside = all(lessThan(pixel, uViewport));
  vec4 picture = uSlabBegin > 0u && inside ? imageLoad(uPicture, pixel) : vec4(0.0);
  for (uint slab = uSlabBegin; slab < uSlabEnd; ++slab) {
    uint bucket = tile * uSlabCount + slab;
    uint begin = offsets[bucket], end = offsets[bucket + 1u];
    if (begin == end) continue;  // the same for the whole group
    // Early termination: the tile is done once none of its pixels can take more.
    bool open = inside && picture.a < uTermination;
    if (!groupOpen(open)) break;
    vec2 depths = slabDepths[slab];
    vec4 sums = vec4(0.0);  // (colour * optical depth, optical depth) of this slab
    for (uint base = begin; base < end; base += kBatch) {
      loadBatchEntry(base + gl_LocalInvocationIndex, end, gl_LocalInvocationIndex);
      barrier();
      uint n = min(kBatch, end - base);
      // Eight splats an iteration: llvmpipe ends a shader's loops after 65535 iterations in all
      // (LP_MAX_TGSI_LOOP_ITERATIONS), which a busy tile's slabs reach one splat at a time.
      for (uint j = 0u; open && j < n; j += 8u) {
        sums += splatAt(j, n, centre, depths, kept) + splatAt(j + 1u, n, centre, depths, kept) +
                splatAt(j + 2u, n, centre, depths, kept) + splatAt(j + 3u, n, centre, depths, kept) +
                splatAt(j + 4u, n, centre, depths, kept) + splatAt(j + 5u, n, centre, depths, kept) +
                splatAt(j + 6u, n, centre, depths, kept) + splatAt(j + 7u, n, centre, depths, kept);
      }
      barrier();
    }
    // The slab pass's pre-classified composite: opacity 1 - exp(-depth), front to back.
    if (sums.a > 0.0) {
      float alpha = 1.0 - exp(-sums.a);
      picture += (1.0 - picture.a) * vec4(sums.rgb / sums.a * alpha, alpha);
    }
  }
  if (inside) imageStore(uPicture, pixel, picture);
}
#endif
