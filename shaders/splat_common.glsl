// Per-splat setup shared by the point-sprite and quad vertex shaders.
#include "ewa_footprint.glsl"

layout(std430, binding = 0) readonly buffer Splats { uvec2 splats[]; };
layout(std430, binding = 1) readonly buffer Order { uint order[]; };

uniform mat4 uView;          // world -> camera
uniform mat3 uCovariance;    // camera-space kernel covariance W V'' W^T
uniform vec3 uOrigin;
uniform vec3 uSpacing;
uniform float uVoxelVolume;  // sx * sy * sz: g = tau * voxel volume
uniform float uKernelRadius; // world bounding radius of a kernel, for culling
uniform bool uOrthographic;
uniform float uFocalPixels;
uniform float uPixelsPerUnit;
uniform vec2 uViewport;
uniform int uFilter;
uniform float uCutoff;
uniform float uMinSpacing;
uniform float uNearDepth;
uniform uint uFirst;         // offset of this draw's slab in order[]
uniform sampler1D uTransfer; // rgb + extinction tau per world unit

flat out vec2 vCenter;
flat out vec3 vConic;
flat out float vAmplitude;
flat out vec3 vColor;

// Fills the flat outputs for splat number `n` of this draw; false when nothing is to be drawn.
bool setupSplat(uint n, out Footprint fp) {
  uvec2 s = splats[order[uFirst + n]];
  uvec3 ijk = uvec3(s.x & 0xffffu, s.x >> 16, s.y & 0xffffu);
  float value = float(s.y >> 16) / 65535.0;
  int size = textureSize(uTransfer, 0);
  vec4 tf = texture(uTransfer, (value * float(size - 1) + 0.5) / float(size));
  fp.visible = false;
  if (!(tf.a > 0.0)) return false;
  vec3 world = uOrigin + vec3(ijk) * uSpacing;
  vec3 u = (uView * vec4(world, 1.0)).xyz;
  Projection proj = Projection(uOrthographic, uFocalPixels, uPixelsPerUnit, 0.5 * uViewport,
                               uViewport);
  FootprintParams params = FootprintParams(uFilter, uCutoff, uMinSpacing, uNearDepth);
  // Cull before forming the Jacobian; Swan's stretch and the low-pass filter widen kernels.
  float pixelWorld = uOrthographic ? 1.0 / uPixelsPerUnit : max(-u.z, 0.0) / uFocalPixels;
  float stretch = uFilter == kFilterSwan ? max(1.0, pixelWorld / uMinSpacing) : 1.0;
  float radius = uKernelRadius * stretch + sqrt(uCutoff) * pixelWorld;
  if (cullKernel(u, radius, proj, params)) return false;
  fp = computeFootprint(u, uCovariance, proj, params);
  if (!fp.visible) return false;
  vCenter = fp.center;
  vConic = fp.conic;
  vAmplitude = tf.a * uVoxelVolume * fp.peak;
  vColor = tf.rgb;
  return true;
}

vec4 pixelToClip(vec2 pixel) { return vec4(pixel / uViewport * 2.0 - 1.0, 0.0, 1.0); }
