// Turns a slab's sums into premultiplied colour and opacity: pre-classified, its optical depth
// and light; post-classified, its kernel-weighted mean value classified per pixel, alone or,
// pre-integrated, as ray segments between the mean values of the slab's halves and the
// neighbouring slab's.
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
// Front to back: the slab drawn before this one lies in front.
const bool kNeighbourInFront = SLAB_NEIGHBOUR_IN_FRONT != 0;
// This slab's image or its neighbour's is coarser than the picture (uSlabScale, uNeighbourScale).
const bool kScaled = SLAB_SCALED != 0;
// Pre-integrated in quarters: the slab image holds (weight * value, weight) of the first two
// quarters of the slab's depth, uSlabBack those of the last two; segments run between four
// values a slab.
const bool kQuarters = SLAB_QUARTERS != 0 && kPreintegrated;

// Pixels no splat of this slab reached fail the depth test before the shader runs.
layout(early_fragment_tests) in;

uniform sampler2D uSlab;
uniform sampler2D uSlabNormal;  // post with shading: the sum of weight * camera-space normal
uniform sampler1D uTransfer;    // rgb + extinction tau per world unit
uniform bool uOrthographic;
uniform float uFocalPixels;
uniform vec2 uViewport;
uniform sampler2D uPairTable;
uniform sampler2D uPairPrefix;  // extinction integrated over the values, n x 1 (opacity)
uniform sampler2D uNeighbourSlab;  // the sums of the slab drawn before this one
uniform sampler2D uSlabBack;       // kQuarters: this slab's last two quarters
uniform sampler2D uNeighbourBack;  // kQuarters: the neighbour's
uniform bool uNeighbour;           // that slab is this one's neighbour in depth
uniform vec2 uSlabDepths;       // this slab's near and far camera depth
uniform float uPixelsPerUnit;   // orthographic: pixels per world unit
// Slab images may be coarser than the picture (src/core/slab_image_scale.h): pixels a texel a
// side of this slab's image and of the neighbour's; 1: the picture's own pixels.
uniform float uSlabScale;
uniform float uNeighbourScale;

out vec4 outColor;

// This pixel's unit normal (from the slab's summed normals; zero without shading, which
// headlightShade then skips) and direction to the eye: fetched once, shared by the segments.
struct Surface {
  vec3 normal;
  vec3 toEye;
};

// A slab image's sums at the pixel centred at `centre`: its texel, or on a coarser image the
// bilinear mean of the four texels about that point (the sums are band-limited far below its
// texels); that image has a border of one texel (scaledCoordinate in
// src/core/slab_image_scale.h).
vec4 slabSums(sampler2D image, vec2 centre, float scale) {
  if (!kScaled || scale == 1.0) return texelFetch(image, ivec2(floor(centre)), 0);
  vec2 texel = centre / scale + 1.0;
  return texture(image, texel / vec2(textureSize(image, 0)));
}

// The slab's mean value over both halves at the point `centre`; false where no kernel reaches.
bool slabValue(vec2 centre, out float v) {
  vec4 s = slabSums(uSlab, centre, uSlabScale);
  if (kQuarters) s += slabSums(uSlabBack, centre, uSlabScale);
  float w = s.g + s.a;
  v = w > 0.0 ? (s.r + s.b) / w : 0.0;
  return w > 0.0;
}

// d(value)/d(pixel) along the unit step `dir`: central where both neighbours have kernels,
// else one-sided. On a coarser image the neighbours are a texel apart, so the derivative is the
// bilinear mean of the texels' central differences.
float pixelDerivative(vec2 q, vec2 dir, float centre) {
  float span = kScaled ? uSlabScale : 1.0;
  vec2 step = dir * span;
  float ahead, behind;
  bool hasAhead = slabValue(q + step, ahead), hasBehind = slabValue(q - step, behind);
  if (hasAhead && hasBehind) return 0.5 * (ahead - behind) / span;
  if (hasAhead) return (ahead - centre) / span;
  if (hasBehind) return (centre - behind) / span;
  return 0.0;
}

// The gradient of the reconstructed field in camera space (x right, y up, z towards the eye)
// per world unit: across the view from the neighbouring pixels at the slab's middle depth,
// along it from the front half's value to the back half's, half a slab apart. `s`: the sums
// of the halves (in quarters, each half's two quarters added).
vec3 fieldGradient(vec4 s) {
  vec2 q = gl_FragCoord.xy;
  float centre = (s.r + s.b) / max(s.g + s.a, 1e-30);
  float thickness = uSlabDepths.y - uSlabDepths.x;
  float depth = 0.5 * (uSlabDepths.x + uSlabDepths.y);
  float pixelsPerUnit = uOrthographic ? uPixelsPerUnit : uFocalPixels / max(depth, 1e-30);
  bool front = s.g > 0.0, back = s.a > 0.0;
  float along = front && back ? (s.b / s.a - s.r / s.g) / (0.5 * thickness) : 0.0;
  return vec3(pixelDerivative(q, vec2(1.0, 0.0), centre) * pixelsPerUnit,
              pixelDerivative(q, vec2(0.0, 1.0), centre) * pixelsPerUnit, -along);
}

Surface pixelSurface(vec4 s) {
  Surface p = Surface(vec3(0.0), vec3(0.0, 0.0, 1.0));
  if (!kShading) return p;
  vec3 normal = kFieldNormals ? fieldGradient(s)
                              : slabSums(uSlabNormal, gl_FragCoord.xy, uSlabScale).xyz;
  vec2 ray = (gl_FragCoord.xy - 0.5 * uViewport) / uFocalPixels;
  float len = length(normal);
  p.normal = len > 0.0 ? normal / len : vec3(0.0);
  if (!uOrthographic) p.toEye = normalize(vec3(-ray, 1.0));
  return p;
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

// Premultiplied colour and opacity of the ray segment `length` world units long whose value
// runs from `front` to `back` (normalized), as classifySlabPair (slab_preintegration.cpp).
vec4 segment(float front, float back, float length, Surface p) {
  float n = float(textureSize(uPairTable, 0).x);
  vec4 t = texture(uPairTable, (vec2(back, front) * (n - 1.0) + 0.5) / n);
  float alpha = 1.0 - exp(-max(length, 0.0) * segmentExtinction(front, back));
  return vec4(shade(t.rgb, p) * alpha, alpha);
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

// The covered lengths of the slab's quarters (front to back) from their weights.
vec4 quarterLengths(vec4 weights) {
  vec2 box = boxDepths(indexRay(gl_FragCoord.xy));
  float stretch = rayStretch(gl_FragCoord.xy);
  float z0 = uSlabDepths.x, q = 0.25 * (uSlabDepths.y - uSlabDepths.x);
  return vec4(coveredLength(z0, z0 + q, box, stretch, weights.x),
              coveredLength(z0 + q, z0 + 2.0 * q, box, stretch, weights.y),
              coveredLength(z0 + 2.0 * q, uSlabDepths.y - q, box, stretch, weights.z),
              coveredLength(uSlabDepths.y - q, uSlabDepths.y, box, stretch, weights.w));
}

// The covered lengths of the slab's halves (front, back) from their weights.
vec2 halfLengths(vec2 weights) {
  vec2 box = boxDepths(indexRay(gl_FragCoord.xy));
  float stretch = rayStretch(gl_FragCoord.xy);
  float mid = 0.5 * (uSlabDepths.x + uSlabDepths.y);
  return vec2(coveredLength(uSlabDepths.x, mid, box, stretch, weights.x),
              coveredLength(mid, uSlabDepths.y, box, stretch, weights.y));
}

// As preintegrated, with four values a slab: from the neighbour's nearer quarter to this
// slab's first, then between its quarters over each one's covered length (back to front: on
// from its last quarter to the neighbour's).
vec4 preintegratedQuarters(vec4 front, vec4 back) {
  vec4 own = quarterValues(front, back);
  vec4 lengths = quarterLengths(vec4(front.g, front.a, back.g, back.a));
  float other = kNeighbourInFront ? own.x : own.w;
  if (uNeighbour) {
    vec4 nf = slabSums(uNeighbourSlab, gl_FragCoord.xy, uNeighbourScale);
    vec4 nb = slabSums(uNeighbourBack, gl_FragCoord.xy, uNeighbourScale);
    if (nf.g + nf.a + nb.g + nb.a > 0.0) {
      vec4 n = quarterValues(nf, nb);
      other = kNeighbourInFront ? n.w : n.x;
    }
  }
  Surface p = pixelSurface(halfSums(front, back));
  // The five values in depth order; segment i runs from value i to value i + 1.
  float v[5];
  if (kNeighbourInFront) {
    v[0] = other; v[1] = own.x; v[2] = own.y; v[3] = own.z; v[4] = own.w;
  } else {
    v[0] = own.x; v[1] = own.y; v[2] = own.z; v[3] = own.w; v[4] = other;
  }
  vec4 sum = vec4(0.0);
  for (int i = 0; i < 4; ++i) {
    vec4 c = segment(v[i], v[i + 1], lengths[i], p);
    sum += (1.0 - sum.a) * c;
  }
  return sum;
}

vec4 preintegrated(vec4 s) {
  // Segments run between the halves' values: from the neighbour's nearer half to this slab's
  // front half, over the front half's covered length, then to the back half over the back
  // half's (back to front: from the front half to the back half, then on to the neighbour).
  // Over all slabs the lengths add up as without pre-integration, so a constant value gives
  // the same picture, while a transfer-function peak between two values is integrated
  // instead of missed.
  vec2 own = halfValues(s);
  vec2 other = kNeighbourInFront ? own.xx : own.yy;
  if (uNeighbour) {
    vec4 n = slabSums(uNeighbourSlab, gl_FragCoord.xy, uNeighbourScale);
    if (n.g + n.a > 0.0) other = halfValues(n);
  }
  Surface p = pixelSurface(s);
  vec2 lengths = halfLengths(s.ga);
  vec4 first, second;
  if (kNeighbourInFront) {
    first = segment(other.y, own.x, lengths.x, p);
    second = segment(own.x, own.y, lengths.y, p);
  } else {
    first = segment(own.x, own.y, lengths.x, p);
    second = segment(own.y, other.x, lengths.y, p);
  }
  return first + (1.0 - first.a) * second;
}

void main() {
  vec4 s = slabSums(uSlab, gl_FragCoord.xy, uSlabScale);
  if (kQuarters) {
    vec4 back = slabSums(uSlabBack, gl_FragCoord.xy, uSlabScale);
    if (!(s.g + s.a + back.g + back.a > 0.0)) discard;
    outColor = preintegratedQuarters(s, back);
    if (!(outColor.a > 0.0)) discard;
    return;  // blended front to back: (1 - dst.a, 1)
  }
  if (kPost && kPreintegrated) {
    if (!(s.g + s.a > 0.0)) discard;
    outColor = preintegrated(s);
    if (!(outColor.a > 0.0)) discard;
    return;  // blended front to back: (1 - dst.a, 1)
  }
  float depth = max(s.a, 0.0);
  if (!(depth > 0.0)) discard;
  vec3 color;
  if (kPost) {
    // depth is the weight: the length of the ray through the slab the kernels cover, less where
    // they barely reach (silhouettes keep their share and stay anti-aliased), ended at the
    // data's box.
    float value = clamp(s.r / depth, 0.0, 1.0);
    depth = coveredLength(uSlabDepths.x, uSlabDepths.y, boxDepths(indexRay(gl_FragCoord.xy)),
                          rayStretch(gl_FragCoord.xy), depth);
    int size = textureSize(uTransfer, 0);
    vec4 tf = texture(uTransfer, (value * float(size - 1) + 0.5) / float(size));
    color = shade(tf.rgb, pixelSurface(s));
    depth *= tf.a;
    if (!(depth > 0.0)) discard;
  } else {
    color = s.rgb / depth;
  }
  // Opacity 1 - exp(-depth), never the linearized sum, so dense slabs saturate at 1.
  float alpha = 1.0 - exp(-depth);
  outColor = vec4(color * alpha, alpha);  // blended front to back: (1 - dst.a, 1)
}
