// Quad path: splats whose footprint exceeds the point-size limit, as instanced quads.
#include "splat_common.glsl"

uniform float uPointSizeLimit;

void main() {
  Footprint fp;
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
  if (!setupSplat(uint(gl_InstanceID), fp)) return;
  float size = pointSpriteSize(fp, uCutoff);
  if (size <= uPointSizeLimit) return;  // the point path drew it
  // Bounding box of the ellipse r <= cutoff: half extents sqrt(cutoff * a), sqrt(cutoff * c).
  vec2 halfExtent = sqrt(uCutoff * fp.covariance.xz) + 1.0;
  if (missesPassHalf(fp, halfExtent)) return;
  if (occluded(fp.center - halfExtent, fp.center + halfExtent)) {
    if (gl_VertexID == 0) atomicAdd(culledSplats, 1u);  // once per quad
    return;
  }
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 2.0 - 1.0;
  gl_Position = pixelToClip(fp.center + corner * halfExtent);
}
