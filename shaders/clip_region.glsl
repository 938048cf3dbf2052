// Crop box and clipping planes in the splat shaders: a line-for-line mirror of
// src/core/clip_share.cpp. Needs profileErf from ewa_footprint.glsl.
#include "ewa_footprint.glsl"
#include "pixel_ray.glsl"

const int kMaxClipPlanes = 12;     // ClipRegion::kMaxHalfSpaces
const float kClipUnbounded = 1e30;

uniform vec4 uClipPlanes[kMaxClipPlanes];  // camera space: dot(xyz, x) + w >= 0 is kept
uniform int uClipCount;                    // 0: nothing clipped, every share is 1

// The depths [near, far] the planes keep along the ray through `pixel`; empty if near > far.
vec2 clippedDepths(vec2 pixel) {
  vec2 kept = vec2(-kClipUnbounded, kClipUnbounded);
  vec2 q = rayOffset(pixel);
  for (int i = 0; i < uClipCount; ++i) {
    vec4 h = uClipPlanes[i];
    float a, b;
    if (orthographicRays()) {
      a = -h.z;
      b = h.x * q.x + h.y * q.y + h.w;
    } else {
      a = h.x * q.x + h.y * q.y - h.z;
      b = h.w;
    }
    if (a > 0.0)
      kept.x = max(kept.x, -b / a);
    else if (a < 0.0)
      kept.y = min(kept.y, -b / a);
    else if (b < 0.0)
      kept.y = -kClipUnbounded;
  }
  return kept;
}

// The share of the depth Gaussian between the slab's bounds (open: the kernel's tail) and
// inside `kept`: the slab split and the clip cut in one erf difference.
float clippedSlabFraction(float mu, float sigma, float zNear, float zFar, bool openNear,
                          bool openFar, vec2 kept, vec2 profile) {
  float lo = openNear ? kept.x : max(zNear, kept.x);
  float hi = openFar ? kept.y : min(zFar, kept.y);
  if (!(hi > lo)) return 0.0;
  float s = 1.0 / (sqrt(2.0) * sigma);
  return 0.5 * profile.y *
         (profileErf((hi - mu) * s, profile) - profileErf((lo - mu) * s, profile));
}

// True when a kernel centred at camera-space `u` lies more than `reach` outside a plane.
bool clipCullsKernel(vec3 u, float reach) {
  for (int i = 0; i < uClipCount; ++i)
    if (dot(uClipPlanes[i].xyz, u) + uClipPlanes[i].w < -reach) return true;
  return false;
}
