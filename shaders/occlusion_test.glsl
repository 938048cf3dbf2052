// Occlusion culling in the splat vertex shaders: a splat whose whole screen rectangle lies
// over pixels already opaque (the opacity pyramid of shaders/opacity_pyramid.comp.glsl, built
// together with the stencil marks) is not drawn; the stencil would reject each of its
// fragments anyway, so the picture is the same.
uniform bool uOcclusion;     // a pyramid of this frame is bound
uniform sampler2D uOpaque;   // level 0: 2x2 pixel blocks; level m: 2^(m+1) pixels a side
uniform int uOpaqueLevels;
uniform ivec2 uOpaqueSize;   // texels of level 0
layout(std430, binding = 4) buffer Culled { uint culledSplats; };

// The level's size from uOpaqueSize, not textureSize(): llvmpipe returned wrong sizes for a
// level chosen in a vertex shader.
float opaqueTexel(ivec2 t, int level) {
  ivec2 size = max(uOpaqueSize >> level, ivec2(1));
  if (any(greaterThanEqual(t, size))) return 1.0;
  return texelFetch(uOpaque, t, level).r;
}

// True when every pixel that the rectangle [lo, hi] (in pixels, as gl_FragCoord) touches is
// opaque. Four texel fetches at the level where the rectangle spans at most two texels.
bool occluded(vec2 lo, vec2 hi) {
  if (!uOcclusion) return false;
  ivec2 a = max(ivec2(floor(lo)), ivec2(0)) >> 1;
  ivec2 b = ivec2(floor(hi)) >> 1;
  if (any(lessThan(b, a))) return false;  // off screen: the rasterizer drops it anyway
  int level = 0;
  while (level + 1 < uOpaqueLevels && any(greaterThan((b >> level) - (a >> level), ivec2(1))))
    ++level;
  if (any(greaterThan((b >> level) - (a >> level), ivec2(1)))) return false;
  a >>= level;
  b >>= level;
  return min(min(opaqueTexel(a, level), opaqueTexel(ivec2(b.x, a.y), level)),
             min(opaqueTexel(ivec2(a.x, b.y), level), opaqueTexel(b, level))) > 0.5;
}
