// Turns a slab's sums into premultiplied colour and opacity: pre-classified, its optical depth
// and light; post-classified, its kernel-weighted mean value classified per pixel, alone or,
// pre-integrated, as ray segments between the mean values of the slab's halves and the
// neighbouring slab's.
#include "slab_classify.glsl"

// Pixels no splat of this slab reached fail the depth test before the shader runs.
layout(early_fragment_tests) in;

uniform sampler2D uSlab;
uniform sampler2D uSlabNormal;  // post with shading: the sum of weight * camera-space normal
uniform sampler1D uTransfer;    // rgb + extinction tau per world unit
uniform vec2 uViewport;
uniform sampler2D uNeighbourSlab;  // the sums of the slab drawn before this one
uniform sampler2D uSlabBack;       // kQuarters: this slab's last two quarters
uniform sampler2D uNeighbourBack;  // kQuarters: the neighbour's
uniform bool uNeighbour;           // that slab is this one's neighbour in depth
uniform vec2 uSlabDepths;       // this slab's near and far camera depth
// Slab images may be coarser than the picture (src/core/slab_image_scale.h): pixels a texel a
// side of this slab's image and of the neighbour's; 1: the picture's own pixels.
uniform float uSlabScale;
uniform float uNeighbourScale;

out vec4 outColor;

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
  return pixelDerivativeFrom(hasAhead, ahead, hasBehind, behind, centre, span);
}

// The gradient of the reconstructed field (gradientFrom) from the neighbouring pixels' values.
// `s`: the sums of the halves (in quarters, each half's two quarters added).
vec3 fieldGradient(vec4 s) {
  vec2 q = gl_FragCoord.xy;
  float centre = (s.r + s.b) / max(s.g + s.a, 1e-30);
  return gradientFrom(vec2(pixelDerivative(q, vec2(1.0, 0.0), centre),
                           pixelDerivative(q, vec2(0.0, 1.0), centre)),
                      s, uSlabDepths);
}

Surface pixelSurface(vec4 s) {
  if (!kShading) return Surface(vec3(0.0), vec3(0.0, 0.0, 1.0));
  // Ray normals: per segment (surfaceAt); here only the direction to the eye.
  vec3 normal = kFieldNormals ? fieldGradient(s)
                : kRayNormals ? vec3(0.0)
                              : slabSums(uSlabNormal, gl_FragCoord.xy, uSlabScale).xyz;
  return surfaceFrom(normal, gl_FragCoord.xy, uViewport);
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
  vec4 lengths =
      quarterLengthsAt(gl_FragCoord.xy, uSlabDepths, vec4(front.g, front.a, back.g, back.a));
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
  return segmentsThrough(v, lengths, p, gl_FragCoord.xy, segmentMiddles(uSlabDepths));
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
  // Ray normals: each segment's from its middle, front to back at the slab's front plane and
  // middle, back to front at its middle and back plane.
  vec2 q = gl_FragCoord.xy;
  float mid = 0.5 * (uSlabDepths.x + uSlabDepths.y);
  vec4 first, second;
  if (kNeighbourInFront) {
    first = segmentAt(other.y, own.x, lengths.x, p, q, uSlabDepths.x);
    second = segmentAt(own.x, own.y, lengths.y, p, q, mid);
  } else {
    first = segmentAt(own.x, own.y, lengths.x, p, q, mid);
    second = segmentAt(own.y, other.x, lengths.y, p, q, uSlabDepths.y);
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
    depth *= tf.a;
    if (!(depth > 0.0)) discard;
    color = shade(tf.rgb, surfaceAt(pixelSurface(s), gl_FragCoord.xy,
                                    0.5 * (uSlabDepths.x + uSlabDepths.y)));
  } else {
    color = s.rgb / depth;
  }
  // Opacity 1 - exp(-depth), never the linearized sum, so dense slabs saturate at 1.
  float alpha = 1.0 - exp(-depth);
  outColor = vec4(color * alpha, alpha);  // blended front to back: (1 - dst.a, 1)
}
