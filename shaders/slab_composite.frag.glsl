// Turns a slab's sums into premultiplied colour and opacity: pre-classified, its optical depth
// and light; post-classified, its kernel-weighted mean value classified per pixel.
#include "headlight.glsl"

uniform sampler2D uSlab;
uniform sampler2D uSlabNormal;  // post with shading: the sum of weight * camera-space normal
uniform sampler1D uTransfer;    // rgb + extinction tau per world unit
uniform bool uPost;
uniform bool uOrthographic;
uniform float uFocalPixels;
uniform vec2 uViewport;

out vec4 outColor;

void main() {
  vec4 s = texelFetch(uSlab, ivec2(gl_FragCoord.xy), 0);
  float depth = max(s.a, 0.0);
  if (!(depth > 0.0)) discard;
  vec3 color;
  if (uPost) {
    // depth is the weight: the length of the ray through the slab the kernels cover, less where
    // they barely reach (silhouettes keep their share and stay anti-aliased).
    float value = clamp(s.r / depth, 0.0, 1.0);
    int size = textureSize(uTransfer, 0);
    vec4 tf = texture(uTransfer, (value * float(size - 1) + 0.5) / float(size));
    color = tf.rgb;
    if (uShading) {
      vec3 normal = texelFetch(uSlabNormal, ivec2(gl_FragCoord.xy), 0).xyz;
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
