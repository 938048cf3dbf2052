// Occlusion culling's opacity pyramid: level 0 holds, per 2x2 block of pixels, 1 where every
// pixel's accumulated opacity reached the early-termination threshold (the pixels the stencil
// marks), else 0; each further level the minimum of the 2x2 texels below it. Texels beyond
// the image are 1: no fragment is drawn there, so they never keep a splat alive.
layout(local_size_x = 8, local_size_y = 8) in;

uniform int uLevel;          // the level written; 0 reads the accumulated image
uniform sampler2D uAccum;    // premultiplied colour and opacity, front to back
uniform float uThreshold;    // the early-termination opacity
uniform ivec2 uImageSize;    // pixels of the accumulated image
layout(r8, binding = 0) uniform readonly image2D uBelow;   // level uLevel - 1
layout(r8, binding = 1) uniform writeonly image2D uLevelOut;

float opaquePixel(ivec2 p) {
  if (any(greaterThanEqual(p, uImageSize))) return 1.0;
  return texelFetch(uAccum, p, 0).a >= uThreshold ? 1.0 : 0.0;
}

float belowTexel(ivec2 p) {
  if (any(greaterThanEqual(p, imageSize(uBelow)))) return 1.0;
  return imageLoad(uBelow, p).r;
}

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, imageSize(uLevelOut)))) return;
  ivec2 p = 2 * t;
  float m;
  if (uLevel == 0)
    m = min(min(opaquePixel(p), opaquePixel(p + ivec2(1, 0))),
            min(opaquePixel(p + ivec2(0, 1)), opaquePixel(p + ivec2(1, 1))));
  else
    m = min(min(belowTexel(p), belowTexel(p + ivec2(1, 0))),
            min(belowTexel(p + ivec2(0, 1)), belowTexel(p + ivec2(1, 1))));
  imageStore(uLevelOut, t, vec4(m));
}
