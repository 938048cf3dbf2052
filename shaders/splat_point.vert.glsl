// Point-sprite path: one point per splat, sized to cover its footprint ellipse.
#include "splat_common.glsl"

uniform float uPointSizeLimit;

void main() {
  Footprint fp;
  gl_PointSize = 0.0;
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: not drawn
  if (!setupSplat(uint(gl_VertexID), fp)) return;
  float size = pointSpriteSize(fp, uCutoff);
  if (size > uPointSizeLimit) return;  // the quad path draws it
  if (missesPassHalf(fp, vec2(0.5 * size))) return;
  if (occluded(fp.center - (0.5 * size + 1.0), fp.center + (0.5 * size + 1.0))) {
    atomicAdd(culledSplats, 1u);
    return;
  }
  gl_PointSize = size;
  gl_Position = pixelToClip(fp.center);
}
