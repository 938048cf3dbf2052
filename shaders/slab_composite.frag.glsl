// Turns a slab's sums into premultiplied colour and opacity: pre-classified, its optical depth
// and light; post-classified, its kernel-weighted mean value classified per pixel, alone or
// with the neighbouring slab's through the pre-integration table.
#include "headlight.glsl"

uniform sampler2D uSlab;
uniform sampler2D uSlabNormal;  // post with shading: the sum of weight * camera-space normal
uniform sampler1D uTransfer;    // rgb + extinction tau per world unit
uniform bool uPost;
uniform bool uOrthographic;
uniform float uFocalPixels;
uniform vec2 uViewport;
// Pre-integration (post only): the table of slab_preintegration.h, x the back value, y the
// front; rgb colour per unit opacity, a mean extinction per world unit.
uniform bool uPreintegrated;
uniform sampler2D uPairTable;
uniform sampler2D uNeighbourSlab;  // the sums of the slab drawn before this one
uniform bool uNeighbour;           // that slab is this one's neighbour in depth
uniform bool uNeighbourInFront;    // front to back: it lies in front

out vec4 outColor;

// Classifies the ray segment whose value runs from `front` to `back` (normalized): colour per
// unit opacity and mean extinction, as classifySlabPair (slab_preintegration.cpp) reads them.
vec4 pairLookup(float front, float back) {
  float n = float(textureSize(uPairTable, 0).x);
  return texture(uPairTable, (vec2(back, front) * (n - 1.0) + 0.5) / n);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 s = texelFetch(uSlab, pixel, 0);
  float depth = max(s.a, 0.0);
  if (!(depth > 0.0)) discard;
  vec3 color;
  if (uPost) {
    // depth is the weight: the length of the ray through the slab the kernels cover, less where
    // they barely reach (silhouettes keep their share and stay anti-aliased).
    float value = clamp(s.r / depth, 0.0, 1.0);
    vec4 tf;
    if (uPreintegrated) {
      // The segment from the neighbouring slab's value to this one's, as long as this slab's
      // covered length: over all slabs the lengths add up as without pre-integration, so a
      // constant value gives the same picture, while a transfer-function peak between two
      // slab values is integrated instead of missed.
      float other = value;
      if (uNeighbour) {
        vec4 n = texelFetch(uNeighbourSlab, pixel, 0);
        if (n.a > 0.0) other = clamp(n.r / n.a, 0.0, 1.0);
      }
      tf = uNeighbourInFront ? pairLookup(other, value) : pairLookup(value, other);
    } else {
      int size = textureSize(uTransfer, 0);
      tf = texture(uTransfer, (value * float(size - 1) + 0.5) / float(size));
    }
    color = tf.rgb;
    if (uShading) {
      vec3 normal = texelFetch(uSlabNormal, pixel, 0).xyz;
      vec2 ray = (gl_FragCoord.xy - 0.5 * uViewport) / uFocalPixels;
      vec3 toEye = uOrthographic ? vec3(0.0, 0.0, 1.0) : normalize(vec3(-ray, 1.0));
      float len = length(normal);
      color = headlightShade(color, len > 0.0 ? normal / len : vec3(0.0), toEye);
    }
    depth *= tf.a;
    if (!(depth > 0.0)) discard;
  } else {
    color = s.rgb / depth;
  }
  // Opacity 1 - exp(-depth), never the linearized sum, so dense slabs saturate at 1.
  float alpha = 1.0 - exp(-depth);
  outColor = vec4(color * alpha, alpha);  // blended front to back: (1 - dst.a, 1)
}
