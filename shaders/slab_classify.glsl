// A slab's sums classified per pixel: the slab pass's variant flags and the pure formulas of
// post-classification (pre-integrated segments through the pair table, the values and covered
// lengths of a slab's quarters, the shaded surface), shared by the slab pass
// (slab_composite.frag.glsl) and the compute tiles (tile_ewa_post.comp.glsl).
#include "headlight.glsl"
#include "covered_length.glsl"

// The variant, fixed when the program is compiled (src/render/slab_pass_programs.h).
#ifndef SLAB_POST
#define SLAB_POST 0
#endif
#ifndef SLAB_PREINTEGRATED
#define SLAB_PREINTEGRATED 0
#endif
#ifndef SLAB_SHADING
#define SLAB_SHADING 0
#endif
#ifndef SLAB_FIELD_NORMALS
#define SLAB_FIELD_NORMALS 0
#endif
#ifndef SLAB_RAY_NORMALS
#define SLAB_RAY_NORMALS 0
#endif
#ifndef SLAB_NEIGHBOUR_IN_FRONT
#define SLAB_NEIGHBOUR_IN_FRONT 0
#endif
#ifndef SLAB_SCALED
#define SLAB_SCALED 0
#endif
#ifndef SLAB_QUARTERS
#define SLAB_QUARTERS 0
#endif
const bool kPost = SLAB_POST != 0;
// Pre-integration (post only): the table of slab_preintegration.h, x the back value, y the
// front; rgb colour per unit opacity, a mean extinction per world unit. The slabs then hold
// (weight * value, weight) of their front half, then of their back half.
const bool kPreintegrated = SLAB_PREINTEGRATED != 0;
const bool kShading = SLAB_SHADING != 0;
// Pre-integrated with shading: normals from the gradient of the reconstructed field, by
// differences of the slab's mean values to the neighbouring pixels and between its halves.
const bool kFieldNormals = SLAB_FIELD_NORMALS != 0;
// Shaded: each segment's normal is the data's gradient read along the pixel's ray at the
// segment's middle (src/render/gradient_texture.h), as a ray caster shades its samples.
const bool kRayNormals = SLAB_RAY_NORMALS != 0 && kShading;
// Front to back: the slab drawn before this one lies in front.
const bool kNeighbourInFront = SLAB_NEIGHBOUR_IN_FRONT != 0;
// This slab's image or its neighbour's is coarser than the picture (uSlabScale, uNeighbourScale).
const bool kScaled = SLAB_SCALED != 0;
// Pre-integrated in quarters: the slab image holds (weight * value, weight) of the first two
// quarters of the slab's depth, uSlabBack those of the last two; segments run between four
// values a slab.
const bool kQuarters = SLAB_QUARTERS != 0 && kPreintegrated;

uniform bool uOrthographic;
uniform float uFocalPixels;
uniform float uPixelsPerUnit;   // orthographic: pixels per world unit
uniform sampler2D uPairTable;
uniform sampler2D uPairPrefix;  // extinction integrated over the values, n x 1 (opacity)
// Ray normals: the gradient per index step over its largest component, (g + 1) / 2 in RGB10_A2
// (src/core/gradient_volume.h); trilinear, voxel centres at texel centres.
uniform sampler3D uGradient;

// A pixel's unit normal (zero without shading, which headlightShade then skips) and direction
// to the eye: found once, shared by the segments.
struct Surface {
  vec3 normal;
  vec3 toEye;
};

// The surface at `pixel` of a `viewport`-sized picture with the gradient (or summed normal)
// `normal`.
Surface surfaceFrom(vec3 normal, vec2 pixel, vec2 viewport) {
  Surface p = Surface(vec3(0.0), vec3(0.0, 0.0, 1.0));
  if (!kShading) return p;
  vec2 ray = (pixel - 0.5 * viewport) / uFocalPixels;
  float len = length(normal);
  p.normal = len > 0.0 ? normal / len : vec3(0.0);
  if (!uOrthographic) p.toEye = normalize(vec3(-ray, 1.0));
  return p;
}

// The data's gradient in camera space at depth `depth` of the ray through `pixel` (its scale
// is the texture's: only its direction counts): sampleGradient (src/core/gradient_volume.cpp)
// at that point's index coordinates, turned by the transpose of the camera-to-index matrix.
vec3 rayGradient(vec2 pixel, float depth) {
  mat2x3 ray = indexRay(pixel);
  vec3 index = ray[0] + depth * ray[1];
  vec3 texel = texture(uGradient, (index + 0.5) / vec3(textureSize(uGradient, 0))).rgb;
  vec3 g = (texel * 1023.0 - 512.0) / 511.0;  // unpackGradient
  return transpose(mat3(uCameraToIndex)) * g;
}

// The surface `p` with ray normals: its normal the data's gradient at `depth` along the ray
// through `pixel`; `p` itself otherwise.
Surface surfaceAt(Surface p, vec2 pixel, float depth) {
  if (!kRayNormals) return p;
  vec3 g = rayGradient(pixel, depth);
  float len = length(g);
  p.normal = len > 0.0 ? g / len : vec3(0.0);
  return p;
}

// The middles of the four segments segmentsThrough draws in the slab between `depths`: front
// to back each ends at a quarter's middle, starting at the one before (the neighbour's last for
// the first), back to front each starts at a quarter's middle.
vec4 segmentMiddles(vec2 depths) {
  float q = 0.25 * (depths.y - depths.x);
  float first = kNeighbourInFront ? depths.x : depths.x + q;
  return first + q * vec4(0.0, 1.0, 2.0, 3.0);
}

// d(value)/d(pixel) from the values `span` pixels ahead and behind: central where both have
// kernels, else one-sided (pixelDerivativeOf in src/core/field_gradient.h).
float pixelDerivativeFrom(bool hasAhead, float ahead, bool hasBehind, float behind, float centre,
                          float span) {
  if (hasAhead && hasBehind) return 0.5 * (ahead - behind) / span;
  if (hasAhead) return (ahead - centre) / span;
  if (hasBehind) return (centre - behind) / span;
  return 0.0;
}

// Changes of the value (in [0, 1]) smaller than this across a pixel and half a slab are the
// float sums' rounding (uniform data's field): no direction.
const float kFlatChange = 1e-5;

// The gradient of the reconstructed field in camera space (x right, y up, z towards the eye)
// per world unit: across the view from `derivatives` (per pixel, x and y) at the slab's middle
// depth, along it from the front half's value to the back half's, half a slab apart. `s`: the
// sums of the halves; `depths`: the slab's near and far camera depth. The mirror of
// fieldGradientOf in src/core/field_gradient.h.
vec3 gradientFrom(vec2 derivatives, vec4 s, vec2 depths) {
  float thickness = depths.y - depths.x;
  float depth = 0.5 * (depths.x + depths.y);
  float pixelsPerUnit = uOrthographic ? uPixelsPerUnit : uFocalPixels / max(depth, 1e-30);
  bool front = s.g > 0.0, back = s.a > 0.0;
  float change = front && back ? s.b / s.a - s.r / s.g : 0.0;
  // Rounding only: no gradient, drawn unshaded.
  float largest = max(max(abs(derivatives.x), abs(derivatives.y)), abs(change));
  if (largest < kFlatChange) return vec3(0.0);
  return vec3(derivatives * pixelsPerUnit, -change / (0.5 * thickness));
}

vec3 shade(vec3 color, Surface p) {
  return kShading ? headlightShade(color, p.normal, p.toEye) : color;
}

// The extinction prefix (n samples) read linearly at normalized value x.
float prefixAt(float x, float n) {
  return texture(uPairPrefix, vec2((clamp(x, 0.0, 1.0) * (n - 1.0) + 0.5) / n, 0.5)).r;
}

// Mean extinction of the segment, as segmentExtinction: from the prefix over at least one
// sample's width about the middle.
float segmentExtinction(float front, float back) {
  float n = float(textureSize(uPairPrefix, 0).x);
  float mid = 0.5 * (front + back);
  float halfWidth = 0.5 * max(abs(back - front), 1.0 / (n - 1.0));
  float a = clamp(mid - halfWidth, 0.0, 1.0), b = clamp(mid + halfWidth, 0.0, 1.0);
  return b > a ? max(0.0, (prefixAt(b, n) - prefixAt(a, n)) / (b - a)) : 0.0;
}

// The colour per unit opacity (rgb) and the opacity (a) of the ray segment `length` world
// units long whose value runs from `front` to `back` (normalized), as classifySlabPair
// (slab_preintegration.cpp).
vec4 segmentColour(float front, float back, float length) {
  float n = float(textureSize(uPairTable, 0).x);
  vec4 t = texture(uPairTable, (vec2(back, front) * (n - 1.0) + 0.5) / n);
  return vec4(t.rgb, 1.0 - exp(-max(length, 0.0) * segmentExtinction(front, back)));
}

// That segment premultiplied and lit by `p`.
vec4 segment(float front, float back, float length, Surface p) {
  vec4 c = segmentColour(front, back, length);
  return vec4(shade(c.rgb, p) * c.a, c.a);
}

// The same lit, with ray normals, by the gradient at `depth` along the ray through `pixel`,
// read only where the segment has opacity (no faster on llvmpipe, measured; a GPU may skip
// the reads for warps of empty segments).
vec4 segmentAt(float front, float back, float length, Surface p, vec2 pixel, float depth) {
  vec4 c = segmentColour(front, back, length);
  if (kRayNormals && c.a > 0.0) p = surfaceAt(p, pixel, depth);
  return vec4(shade(c.rgb, p) * c.a, c.a);
}

// The segments from value i to value i + 1 of `v` (depth order) over `lengths`, composited
// front to back, on the ray through `pixel`; with ray normals each lit by the gradient at its
// middle (`middles`: segmentMiddles).
vec4 segmentsThrough(float v[5], vec4 lengths, Surface p, vec2 pixel, vec4 middles) {
  vec4 sum = vec4(0.0);
  for (int i = 0; i < 4; ++i) {
    vec4 c = segmentAt(v[i], v[i + 1], lengths[i], p, pixel, middles[i]);
    sum += (1.0 - sum.a) * c;
  }
  return sum;
}

// Mean values of a slab's halves (front, back); a half without weight takes the other's.
vec2 halfValues(vec4 s) {
  float front = s.g > 0.0 ? s.r / s.g : s.b / s.a;
  float back = s.a > 0.0 ? s.b / s.a : front;
  return clamp(vec2(front, back), 0.0, 1.0);
}

// The sums of the halves from those of the quarters (front image, back image).
vec4 halfSums(vec4 front, vec4 back) {
  return vec4(front.r + front.b, front.g + front.a, back.r + back.b, back.g + back.a);
}

// Mean values of a slab's quarters, front to back; a quarter without weight takes the slab's
// mean (it ends or starts only segments of no length).
vec4 quarterValues(vec4 front, vec4 back) {
  vec4 sums = vec4(front.r, front.b, back.r, back.b);
  vec4 weights = vec4(front.g, front.a, back.g, back.a);
  float mean = dot(sums, vec4(1.0)) / max(dot(weights, vec4(1.0)), 1e-30);
  vec4 v = vec4(mean);
  for (int i = 0; i < 4; ++i)
    if (weights[i] > 0.0) v[i] = sums[i] / weights[i];
  return clamp(v, 0.0, 1.0);
}

// The covered lengths of the quarters (front to back) of the slab between `depths` at `pixel`
// from their weights.
vec4 quarterLengthsAt(vec2 pixel, vec2 depths, vec4 weights) {
  vec2 box = boxDepths(indexRay(pixel));
  float stretch = rayStretch(pixel);
  float z0 = depths.x, q = 0.25 * (depths.y - depths.x);
  return vec4(coveredLength(z0, z0 + q, box, stretch, weights.x),
              coveredLength(z0 + q, z0 + 2.0 * q, box, stretch, weights.y),
              coveredLength(z0 + 2.0 * q, depths.y - q, box, stretch, weights.z),
              coveredLength(depths.y - q, depths.y, box, stretch, weights.w));
}
