// Turns a slab's sums into premultiplied colour and opacity: pre-classified, its optical depth
// and light; post-classified, its kernel-weighted mean value classified per pixel, alone or,
// pre-integrated, as ray segments between the mean values of the slab's halves and the
// neighbouring slab's.
#include "headlight.glsl"

uniform sampler2D uSlab;
uniform sampler2D uSlabNormal;  // post with shading: the sum of weight * camera-space normal
uniform sampler1D uTransfer;    // rgb + extinction tau per world unit
uniform bool uPost;
uniform bool uOrthographic;
uniform float uFocalPixels;
uniform vec2 uViewport;
// Pre-integration (post only): the table of slab_preintegration.h, x the back value, y the
// front; rgb colour per unit opacity, a mean extinction per world unit. The slabs then hold
// (weight * value, weight) of their front half, then of their back half.
uniform bool uPreintegrated;
uniform sampler2D uPairTable;
uniform sampler2D uNeighbourSlab;  // the sums of the slab drawn before this one
uniform bool uNeighbour;           // that slab is this one's neighbour in depth
uniform bool uNeighbourInFront;    // front to back: it lies in front

out vec4 outColor;

// This pixel's unit normal (from the slab's summed normals; zero without shading, which
// headlightShade then skips) and direction to the eye: fetched once, shared by the segments.
struct Surface {
  vec3 normal;
  vec3 toEye;
};

Surface pixelSurface() {
  Surface p = Surface(vec3(0.0), vec3(0.0, 0.0, 1.0));
  if (!uShading) return p;
  vec3 normal = texelFetch(uSlabNormal, ivec2(gl_FragCoord.xy), 0).xyz;
  vec2 ray = (gl_FragCoord.xy - 0.5 * uViewport) / uFocalPixels;
  float len = length(normal);
  p.normal = len > 0.0 ? normal / len : vec3(0.0);
  if (!uOrthographic) p.toEye = normalize(vec3(-ray, 1.0));
  return p;
}

vec3 shade(vec3 color, Surface p) { return headlightShade(color, p.normal, p.toEye); }

// Premultiplied colour and opacity of the ray segment `length` world units long whose value
// runs from `front` to `back` (normalized), as classifySlabPair (slab_preintegration.cpp).
vec4 segment(float front, float back, float length, Surface p) {
  float n = float(textureSize(uPairTable, 0).x);
  vec4 t = texture(uPairTable, (vec2(back, front) * (n - 1.0) + 0.5) / n);
  float alpha = 1.0 - exp(-max(length, 0.0) * t.a);
  return vec4(shade(t.rgb, p) * alpha, alpha);
}

// Mean values of a slab's halves (front, back); a half without weight takes the other's.
vec2 halfValues(vec4 s) {
  float front = s.g > 0.0 ? s.r / s.g : s.b / s.a;
  float back = s.a > 0.0 ? s.b / s.a : front;
  return clamp(vec2(front, back), 0.0, 1.0);
}

vec4 preintegrated(vec4 s) {
  // Segments run between the halves' values: from the neighbour's nearer half to this slab's
  // front half, over the front half's covered length, then to the back half over the back
  // half's (back to front: from the front half to the back half, then on to the neighbour).
  // Over all slabs the lengths add up as without pre-integration, so a constant value gives
  // the same picture, while a transfer-function peak between two values is integrated
  // instead of missed.
  vec2 own = halfValues(s);
  vec2 other = uNeighbourInFront ? own.xx : own.yy;
  if (uNeighbour) {
    vec4 n = texelFetch(uNeighbourSlab, ivec2(gl_FragCoord.xy), 0);
    if (n.g + n.a > 0.0) other = halfValues(n);
  }
  Surface p = pixelSurface();
  vec4 first, second;
  if (uNeighbourInFront) {
    first = segment(other.y, own.x, s.g, p);
    second = segment(own.x, own.y, s.a, p);
  } else {
    first = segment(own.x, own.y, s.g, p);
    second = segment(own.y, other.x, s.a, p);
  }
  return first + (1.0 - first.a) * second;
}

void main() {
  vec4 s = texelFetch(uSlab, ivec2(gl_FragCoord.xy), 0);
  if (uPost && uPreintegrated) {
    if (!(s.g + s.a > 0.0)) discard;
    outColor = preintegrated(s);
    if (!(outColor.a > 0.0)) discard;
    return;  // blended front to back: (1 - dst.a, 1)
  }
  float depth = max(s.a, 0.0);
  if (!(depth > 0.0)) discard;
  vec3 color;
  if (uPost) {
    // depth is the weight: the length of the ray through the slab the kernels cover, less where
    // they barely reach (silhouettes keep their share and stay anti-aliased).
    float value = clamp(s.r / depth, 0.0, 1.0);
    int size = textureSize(uTransfer, 0);
    vec4 tf = texture(uTransfer, (value * float(size - 1) + 0.5) / float(size));
    color = shade(tf.rgb, pixelSurface());
    depth *= tf.a;
    if (!(depth > 0.0)) discard;
  } else {
    color = s.rgb / depth;
  }
  // Opacity 1 - exp(-depth), never the linearized sum, so dense slabs saturate at 1.
  float alpha = 1.0 - exp(-depth);
  outColor = vec4(color * alpha, alpha);  // blended front to back: (1 - dst.a, 1)
}
