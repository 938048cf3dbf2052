// The compute EWA splatter's post-classified composite (the lists are tile_ewa.comp.glsl's,
// binned with a border of one pixel where the normals come from the field): one work group a
// tile (and that border), each slab's kernel-weighted values and weights added up per pixel in
// quarters of the slab's depth with their exact depth share, then classified as the slab pass
// classifies a slab image (slab_classify.glsl: pre-integrated segments from the slab in front,
// shaded with normals from the neighbouring pixels' values or the gradient texture), composited
// front to back.
#define SLAB_POST 1
#define SLAB_PREINTEGRATED 1
#define SLAB_QUARTERS 1
#define SLAB_NEIGHBOUR_IN_FRONT 1
#include "ewa_footprint.glsl"
#include "clip_region.glsl"
#include "slab_classify.glsl"

// The records of tile_ewa.comp.glsl, the value in place of the unused fourth colour channel:
// (box), (conic, weight at the centre), (depth, slopes, depth sigma), (colour, value).
layout(std430, binding = 0) readonly buffer Splats { vec4 splats[]; };
layout(std430, binding = 2) readonly buffer Offsets { uint offsets[]; };  // per bucket
layout(std430, binding = 4) readonly buffer Lists { uint lists[]; };   // splat | flags
layout(std430, binding = 5) readonly buffer Slabs { vec2 slabDepths[]; };  // near, far

const uint kFirstSlab = 1u << 31;  // src/core/slab_partition.h
const uint kLastSlab = 1u << 30;
const uint kIndexMask = kLastSlab - 1u;

uniform uint uSlabCount;  // bucket (tile, slab) is tile * uSlabCount + slab
uniform ivec2 uTiles;     // tiles across and up
uniform ivec2 uViewport;  // pixels
uniform float uCutoff;
uniform vec2 uDepthProfile;  // DepthProfile, as the splat fragments take it
uniform float uTermination;  // a pixel stops at this opacity

// Field normals read the neighbouring pixels' values: a border of one pixel about the tile,
// whose pixels add up their sums for them. Unshaded and ray-normal frames need none: 256
// invocations a 16-pixel tile instead of 324, over fewer binned splats.
const int kBorder = kShading && !kRayNormals ? 1 : 0;
const int kSide = TILE_SIZE + 2 * kBorder;  // the tile and its border
const uint kBatch = uint(kSide * kSide);
// One row of invocations, the tile's rows one after another: laid out 10 x 10, llvmpipe left
// every row's ninth invocation's pixel empty (18 x 18 drew right).
layout(local_size_x = kSide * kSide) in;
// Premultiplied, front to back; a draw in chunks of slabs carries it from one to the next, with
// the sums of the last slab's quarters (for the segments from it to the next chunk's first).
layout(rgba32f, binding = 0) uniform image2D uPicture;
layout(rgba32f, binding = 1) uniform image2D uLastFront;
layout(rgba32f, binding = 2) uniform image2D uLastBack;
uniform uint uSlabBegin;  // this dispatch's slabs: [uSlabBegin, uSlabEnd)
uniform uint uSlabEnd;
#include "tile_batch.glsl"
shared float slabValues[kBatch];  // each pixel's mean value in the slab, for its neighbours
shared uint weighted[kBatch];     // that pixel has kernels in the slab

// Adds batch splat j (none past n) at the pixel centred at `centre`, in the slab between
// `depths`, to the sums of the slab's first two quarters (weight * value, weight, weight *
// value, weight) and of its last two, as the splat fragments add them (clipped: inside the
// depths `kept`).
void addSplat(uint j, uint n, vec2 centre, vec2 depths, vec2 kept, inout vec4 front,
              inout vec4 back) {
  vec2 dx;
  float r;
  if (!batchFootprint(j, n, centre, dx, r)) return;
  vec4 q = batch[4u * j + 1u];
  vec4 z = batch[4u * j + 2u];
  uint flags = batchOpen[j];
  vec4 d = q.w * windowedGaussian(r, uCutoff) *
           slabQuarters(z.x + dot(z.yz, dx), z.w, depths.x, depths.y, (flags & kFirstSlab) != 0u,
                        (flags & kLastSlab) != 0u, kept, uDepthProfile);
  float v = batch[4u * j + 3u].w;
  front += vec4(v * d.x, d.x, v * d.y, d.y);
  back += vec4(v * d.z, d.z, v * d.w, d.w);
}

// SplatRenderer::slabsAdjacent on float depths.
bool adjacent(vec2 a, vec2 b) {
  return abs(a.y - b.x) <= 1e-5 * max(max(a.y - a.x, b.y - b.x), abs(b.x));
}

void main() {
  uint tile = gl_WorkGroupID.y * uint(uTiles.x) + gl_WorkGroupID.x;
  uint me = gl_LocalInvocationIndex;
  ivec2 local = ivec2(int(me) % kSide, int(me) / kSide);
  ivec2 pixel = ivec2(gl_WorkGroupID.xy) * TILE_SIZE + local - kBorder;
  vec2 centre = vec2(pixel) + 0.5;
  vec2 kept = clippedDepths(centre);  // the crop box and clipping planes along this ray
  bool inside = all(greaterThanEqual(pixel, ivec2(0))) && all(lessThan(pixel, uViewport));
  bool own = inside && all(greaterThanEqual(local, ivec2(kBorder))) &&
             all(lessThan(local, ivec2(kSide - kBorder)));
  vec4 picture = vec4(0.0);
  vec4 lastFront = vec4(0.0), lastBack = vec4(0.0);  // the slab before's sums (none: zero)
  if (uSlabBegin > 0u && own) {
    picture = imageLoad(uPicture, pixel);
    lastFront = imageLoad(uLastFront, pixel);
    lastBack = imageLoad(uLastBack, pixel);
  }
  for (uint slab = uSlabBegin; slab < uSlabEnd; ++slab) {
    uint bucket = tile * uSlabCount + slab;
    uint begin = offsets[bucket], end = offsets[bucket + 1u];
    if (begin == end) {  // the same for the whole group
      lastFront = lastBack = vec4(0.0);
      continue;
    }
    // Early termination: the tile is done once none of its own pixels can take more; the
    // border's pixels add up their sums while it is not, for the normals.
    bool open = own && picture.a < uTermination;
    if (!groupOpen(open)) break;
    // The pixels that add up this slab: the open ones, and the border's for their normals
    // (a closed pixel's sums would only feed its neighbours' field normals).
    bool adding = kBorder == 1 ? inside : open;
    vec2 depths = slabDepths[slab];
    vec4 front = vec4(0.0), back = vec4(0.0);
    for (uint base = begin; base < end; base += kBatch) {
      loadBatchEntry(base + me, end, me);
      barrier();
      uint n = min(kBatch, end - base);
      // Eight splats an iteration: llvmpipe ends a shader's loops after 65535 iterations in all
      // (LP_MAX_TGSI_LOOP_ITERATIONS), which the middle tiles of a small picture reached with
      // four (engine at 128^2: 144 levels off in a block of tiles).
      for (uint j = 0u; adding && j < n; j += 8u) {
        addSplat(j, n, centre, depths, kept, front, back);
        addSplat(j + 1u, n, centre, depths, kept, front, back);
        addSplat(j + 2u, n, centre, depths, kept, front, back);
        addSplat(j + 3u, n, centre, depths, kept, front, back);
        addSplat(j + 4u, n, centre, depths, kept, front, back);
        addSplat(j + 5u, n, centre, depths, kept, front, back);
        addSplat(j + 6u, n, centre, depths, kept, front, back);
        addSplat(j + 7u, n, centre, depths, kept, front, back);
      }
      barrier();
    }
    vec4 halves = halfSums(front, back);
    float w = halves.g + halves.a;
    if (kBorder == 1) {
      slabValues[me] = w > 0.0 ? (halves.r + halves.b) / w : 0.0;
      weighted[me] = w > 0.0 ? 1u : 0u;
      barrier();
    }
    if (open && w > 0.0) {
      vec3 normal = vec3(0.0);
      if (kShading && !kRayNormals) {
        float c = slabValues[me];
        uint side = uint(kSide);
        vec2 derivatives = vec2(
            pixelDerivativeFrom(weighted[me + 1u] != 0u, slabValues[me + 1u],
                                weighted[me - 1u] != 0u, slabValues[me - 1u], c, 1.0),
            pixelDerivativeFrom(weighted[me + side] != 0u, slabValues[me + side],
                                weighted[me - side] != 0u, slabValues[me - side], c, 1.0));
        normal = gradientFrom(derivatives, halves, depths);
      }
      Surface p = surfaceFrom(normal, centre, vec2(uViewport));
      vec4 values = quarterValues(front, back);
      float before = values.x;
      if (slab > 0u && adjacent(slabDepths[slab - 1u], depths) &&
          lastFront.g + lastFront.a + lastBack.g + lastBack.a > 0.0)
        before = quarterValues(lastFront, lastBack).w;
      float v[5] = float[5](before, values.x, values.y, values.z, values.w);
      vec4 lengths = quarterLengthsAt(centre, depths, vec4(front.g, front.a, back.g, back.a));
      picture += (1.0 - picture.a) * segmentsThrough(v, lengths, p, centre, segmentMiddles(depths));
    }
    lastFront = front;
    lastBack = back;
  }
  if (!own) return;
  imageStore(uPicture, pixel, picture);
  if (uSlabEnd < uSlabCount) {
    imageStore(uLastFront, pixel, lastFront);
    imageStore(uLastBack, pixel, lastBack);
  }
}
