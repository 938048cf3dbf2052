// The slab partition on the GPU, the mirror of src/core/slab_partition.cpp in four passes
// chosen by a define: EXTENT_PASS (the range and counts of all splats' depth extents),
// COUNT_PASS (splats per slab), SCAN_PASS (first entries, cursors, indirect draw commands and
// the number of entries) and SCATTER_PASS (the order list). Each per-splat pass forms the
// splat's depth extent again from its record (splatExtent) rather than keep 8 bytes a splat
// between passes. Depths are doubles, as in the C++, so both put every kernel in the same slabs.
#define REACH_FLOAT double
#include "kernel_reach.glsl"
#include "dispatch_index.glsl"

const uint kFirstSlab = 0x80000000u;
const uint kLastSlab = 0x40000000u;

layout(std430, binding = 0) readonly buffer Splats { uvec2 splats[]; };
layout(std430, binding = 1) buffer Order { uint order[]; };
layout(std430, binding = 2) readonly buffer Attributes { uvec2 attributes[]; };
layout(std430, binding = 3) buffer SlabFirst { uint slabFirst[]; };
// Ordered bits of the smallest lo, largest hi and nearest centre; splats listed; the entries
// of the order list (written by the scan pass).
layout(std430, binding = 5) buffer Range { uint rangeLo, rangeHi, rangeNearest, rangeSplats,
                                           rangeEntries; };
layout(std430, binding = 6) buffer Cursor { uint cursor[]; };  // counts, then next free entry
// Per slab a DrawArraysIndirectCommand for the points, then one per slab for the quads.
layout(std430, binding = 7) writeonly buffer Commands { uint commands[]; };

uniform uint uCount;       // splats
uniform uint uSlabCount;   // slabs (COUNT, SCAN and SCATTER)
uniform double uLo;        // front of the first slab
uniform double uScale;     // slabs per unit of depth

// A float as a uint whose unsigned order is the float's order (for atomicMin / atomicMax).
uint orderedBits(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}

// The splat of this invocation: the per-splat passes run groups of 256 on a 2D grid.
uint splatIndex() {
  return dispatchIndex(256u);
}

uint slabOf(float d) {
  return min(uSlabCount - 1u, uint(max(0.0lf, (double(d) - uLo) * uScale)));
}

#if !defined(SCAN_PASS)
layout(local_size_x = 256) in;

uniform double uD0;          // depth = uD0 + i uDi + j uDj + k uDk
uniform dvec3 uDijk;
uniform dvec3 uRow;          // world direction of increasing depth
uniform double uVolumeVariance;
uniform dmat3 uRotation;     // world to camera
uniform dvec3 uSigma;       // kernel standard deviations per axis (kernelSigma)
uniform double uCullDepth;
uniform bool uSurfaces;      // attributes are uploaded and hold surface splats
uniform double uCutoff;
uniform double uDepthCutoff;  // KernelReach::depthCutoff
uniform double uMaxSigma;
uniform double uMinSpacing;  // the surface offset's unit
uniform double uSwanSpacing;  // Swan's s: kernel width * smallest spacing
uniform bool uSwan;
uniform bool uOrthographic;
uniform double uFocalPixels;
uniform double uPixelsPerUnit;

// Splat m's depth extent (float near and far depth) and centre depth into e and centre; false
// where it is culled (its centre at or nearer than the near cull). The same code in every pass,
// so they all place a splat alike.
bool splatExtent(uint m, out vec2 e, out double centre) {
  uvec2 s = splats[m];
  precise double d = uD0 + double(s.x & 0xffffu) * uDijk.x + double(s.x >> 16) * uDijk.y +
                     double(s.y & 0xffffu) * uDijk.z;
  precise double variance = uVolumeVariance;  // precise: each pass must form it alike
  uvec2 at = uSurfaces ? attributes[m] : uvec2(0u);  // no surfaces: none uploaded
  if ((at.y >> 16) != 0u) {
    vec2 xy = unpackHalf2x16(at.x), zk = unpackHalf2x16(at.y);
    if (zk.y >= 1.0) {
      dvec3 n = dvec3(xy.x, xy.y, zk.x);
      precise double shift = dot(uRow, n) * (double(zk.y) - 3.0) * uMinSpacing;
      d += shift;
      dmat3 p = dmat3(1.0) - outerProduct(n, n);
      dmat3 v = dmat3(dvec3(uSigma.x * uSigma.x, 0, 0), dvec3(0, uSigma.y * uSigma.y, 0),
                      dvec3(0, 0, uSigma.z * uSigma.z));
      variance = (uRotation * (p * v * p) * transpose(uRotation))[2][2];
    }
  }
  centre = d;
  if (!(d > uCullDepth)) return false;
  KernelReach k = KernelReach(uCutoff, uDepthCutoff, uMaxSigma, uSwanSpacing, uSwan,
                              uOrthographic, uFocalPixels, uPixelsPerUnit);
  precise double radius = depthReach(k, variance, d);
  e = vec2(float(d - radius), float(d + radius));
  return true;
}
#endif

#if defined(EXTENT_PASS)
shared uint groupLo, groupHi, groupNearest, groupSplats;

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    groupLo = 0xffffffffu;
    groupHi = 0u;
    groupNearest = 0xffffffffu;
    groupSplats = 0u;
  }
  barrier();
  uint m = splatIndex();
  vec2 e;
  double d;
  if (m < uCount && splatExtent(m, e, d)) {
    atomicMin(groupLo, orderedBits(e.x));
    atomicMax(groupHi, orderedBits(e.y));
    atomicMin(groupNearest, orderedBits(float(d)));
    atomicAdd(groupSplats, 1u);
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u && groupSplats > 0u) {
    atomicMin(rangeLo, groupLo);
    atomicMax(rangeHi, groupHi);
    atomicMin(rangeNearest, groupNearest);
    atomicAdd(rangeSplats, groupSplats);
  }
}

#elif defined(COUNT_PASS)
void main() {
  uint m = splatIndex();
  vec2 e;
  double d;
  if (m >= uCount || !splatExtent(m, e, d)) return;
  for (uint b = slabOf(e.x), last = slabOf(e.y); b <= last; ++b) atomicAdd(cursor[b], 1u);
}

#elif defined(SCAN_PASS)
// One group: each invocation sums a run of slabs, the runs' sums are scanned in shared memory.
layout(local_size_x = 1024) in;

shared uint runSum[1024];

void main() {
  uint t = gl_LocalInvocationIndex;
  uint per = (uSlabCount + 1023u) / 1024u;
  uint begin = min(t * per, uSlabCount), end = min(begin + per, uSlabCount);
  uint sum = 0u;
  for (uint b = begin; b < end; ++b) sum += cursor[b];
  runSum[t] = sum;
  barrier();
  if (t == 0u) {
    uint total = 0u;
    for (uint r = 0u; r < 1024u; ++r) {
      uint c = runSum[r];
      runSum[r] = total;
      total += c;
    }
    rangeEntries = total;  // the order list's size, read back before the scatter
  }
  barrier();
  uint first = runSum[t];
  for (uint b = begin; b < end; ++b) {
    uint count = cursor[b];
    slabFirst[b] = first;
    cursor[b] = first;
    uint p = 4u * b, q = 4u * (uSlabCount + b);
    commands[p] = count;  // points: count vertices, one instance
    commands[p + 1u] = 1u;
    commands[p + 2u] = 0u;
    commands[p + 3u] = 0u;
    commands[q] = 4u;  // quads: a 4-vertex strip per splat instance
    commands[q + 1u] = count;
    commands[q + 2u] = 0u;
    commands[q + 3u] = 0u;
    first += count;
  }
}

#elif defined(SCATTER_PASS)
void main() {
  uint m = splatIndex();
  vec2 e;
  double d;
  if (m >= uCount || !splatExtent(m, e, d)) return;
  uint b0 = slabOf(e.x), b1 = slabOf(e.y);
  for (uint b = b0; b <= b1; ++b) {
    // Within the slab's share as counted (a splat placed otherwise than in the count pass
    // would lose an entry, never write past its slab or the list).
    uint end = b + 1u < uSlabCount ? slabFirst[b + 1u] : rangeEntries;
    uint at = atomicAdd(cursor[b], 1u);
    if (at < end) order[at] = m | (b == b0 ? kFirstSlab : 0u) | (b == b1 ? kLastSlab : 0u);
  }
}
#endif
