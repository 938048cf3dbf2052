// Per-splat setup shared by the point-sprite and quad vertex shaders (and, with SPLAT_COMPUTE,
// the compute splatter's footprint pass: splatSetup alone, no varyings).
#include "splat_variant.glsl"
#include "ewa_footprint.glsl"
#include "clip_region.glsl"
#include "headlight.glsl"
#include "kernel_reach.glsl"
#include "occlusion_test.glsl"

layout(std430, binding = 1) readonly buffer Order { uint order[]; };
// The splat records (i | j << 16, k | value << 16) and attributes (packHalf2x16(nx, ny),
// packHalf2x16(nz, kind): src/core/splat_attributes.h): storage blocks, or texel buffers where
// the list is larger than a storage block may be (llvmpipe: 128 MiB, 16.8 M splats).
#if SPLAT_TEXEL_BUFFER
uniform usamplerBuffer uSplatTexels;
uniform usamplerBuffer uAttributeTexels;
uvec2 splatRecord(uint index) { return texelFetch(uSplatTexels, int(index)).xy; }
uvec2 splatAttributes(uint index) { return texelFetch(uAttributeTexels, int(index)).xy; }
#else
layout(std430, binding = 0) readonly buffer Splats { uvec2 splats[]; };
layout(std430, binding = 2) readonly buffer Attributes { uvec2 attributes[]; };
uvec2 splatRecord(uint index) { return splats[index]; }
uvec2 splatAttributes(uint index) { return attributes[index]; }
#endif
// The GPU slab partition's first entry of each slab (src/render/gpu_slab_partition.h).
layout(std430, binding = 3) readonly buffer SlabFirst { uint slabFirst[]; };

uniform mat4 uView;          // world -> camera
uniform mat3 uCovariance;    // camera-space kernel covariance W V'' W^T
uniform vec3 uOrigin;
uniform vec3 uSpacing;
uniform vec3 uKernelSigma;   // kernel standard deviations per axis: kernel width * spacing
uniform float uVoxelVolume;  // sx * sy * sz: g = tau * voxel volume
uniform float uMaxSigma;     // a kernel's largest standard deviation (kernel width * spacing)
uniform bool uOrthographic;
uniform float uFocalPixels;
uniform float uPixelsPerUnit;
uniform vec2 uViewport;      // the image drawn into, in pixels (a slab image may be coarser)
uniform vec2 uPrincipal;     // the view axis in that image
uniform vec4 uViewportRect;  // the GL viewport drawn with: origin, size (a guard band wider)
uniform float uLowPass;      // FootprintParams::lowPass
uniform int uFilter;
uniform float uCutoff;
uniform float uDepthCutoff;  // KernelReach::depthCutoff: the slabs a kernel is listed in
uniform float uMinSpacing;   // the surface offset's unit
uniform float uSwanSpacing;  // Swan's s: kernel width * smallest spacing
uniform float uSlabMark;     // clip-space z: the slab's mark in the depth buffer
uniform float uCullDepth;    // kernels at or nearer than this camera depth are culled
uniform uint uFirst;         // offset of this draw's first entry in order[] (as bound)
uniform int uSlabIndex;      // >= 0: the slab's offset is slabFirst[uSlabIndex] instead
uniform sampler1D uTransfer; // rgb + extinction tau per world unit
uniform float uSurfaceTau;   // optical depth of a surface-splat layer along its normal
// Post-classification (kPost, composite only): splats carry their value and camera-space normal
// with unit extinction; the slab pass classifies the kernel-weighted mean per pixel.
// The attributes are uploaded only while a frame uses them (shading or surface splats); else
// every splat is an unshaded volume splat and the buffer is not read.
uniform bool uAttributes;
// The slab's depths and how its kernels are split between slabs (the fragment shader's), and
// which part of the slab a pass sums: a slab's two passes take its front quarters (1), then its
// back ones (2); 0 the whole slab. A kernel whose cut depth profile misses that half adds
// nothing to it and is not drawn (missesPassHalf).
uniform bool uSplitDepth;
uniform bool uOpenTails;
uniform float uSlabNear;
uniform float uSlabFar;
uniform vec2 uDepthProfile;
uniform int uPassHalf;

const uint kFirstSlab = 0x80000000u;
const uint kLastSlab = 0x40000000u;
const uint kIndexMask = 0x3fffffffu;

// The reach of this frame's kernels (src/core/kernel_reach.h).
KernelReach kernelReach() {
  return KernelReach(uCutoff, uDepthCutoff, uMaxSigma, uSwanSpacing, uFilter == kFilterSwan,
                     uOrthographic, uFocalPixels, uPixelsPerUnit);
}

// Sets up splat record `index` for this frame: its footprint, optical depth at the centre
// (amplitude), colour (post: the camera-space normal, for shading per pixel) and normalized
// value; false when nothing is to be drawn.
bool splatSetup(uint index, out Footprint fp, out float amplitude, out vec3 color,
                out float value) {
  uvec2 s = splatRecord(index);
  uvec3 ijk = uvec3(s.x & 0xffffu, s.x >> 16, s.y & 0xffffu);
  value = float(s.y >> 16) / 65535.0;
  int size = textureSize(uTransfer, 0);
  vec4 tf = texture(uTransfer, (value * float(size - 1) + 0.5) / float(size));
  uvec2 at = uAttributes ? splatAttributes(index) : uvec2(0u);
  vec2 nxy = unpackHalf2x16(at.x), nzKind = unpackHalf2x16(at.y);
  vec3 normal = vec3(nxy, nzKind.x);
  bool surface = nzKind.y >= 1.0;
  fp.visible = false;
  // Post: zero-opacity voxels next to visible ones shape the mean value; they stay.
  if (!kPost && !surface && !(tf.a > 0.0)) return false;
  vec3 world = uOrigin + vec3(ijk) * uSpacing;
  mat3 rotation = mat3(uView);
  mat3 cov = uCovariance;
  float mass = (kPost ? 1.0 : tf.a) * uVoxelVolume;
  if (surface) {
    world += normal * ((nzKind.y - 3.0) * uMinSpacing);
    cov = surfaceCovariance(rotation, uKernelSigma, normal);
    mass = surfaceSplatMass(uSpacing, normal, uSurfaceTau);
  }
  vec3 u = (uView * vec4(world, 1.0)).xyz;
  Projection proj = Projection(uOrthographic, uFocalPixels, uPixelsPerUnit, uPrincipal, uViewport);
  FootprintParams params = FootprintParams(uFilter, uCutoff, uSwanSpacing, uCullDepth, uLowPass);
  // Cull before forming the Jacobian.
  float radius = worldReach(kernelReach(), -u.z);
  if (cullKernel(u, radius, proj, params)) return false;
  // Kernels wholly outside the crop box or a clipping plane; twice the cutoff radius, so the
  // Gaussian tail a culled kernel would have left on the kept side is negligible.
  if (clipCullsKernel(u, 2.0 * radius)) return false;
  fp = computeFootprint(u, cov, proj, params);
  if (!fp.visible) return false;
  amplitude = mass * fp.peak;
  vec3 toEye = uOrthographic ? vec3(0.0, 0.0, 1.0) : normalize(-u);
  color = kPost ? rotation * normal : headlightShade(tf.rgb, rotation * normal, toEye);
  return true;
}

#ifndef SPLAT_COMPUTE
flat out vec2 vCenter;
flat out vec3 vConic;
flat out float vAmplitude;
flat out vec3 vColor;       // post: the camera-space normal, for shading per pixel
flat out float vValue;       // normalized value, for MIP and post-classification
flat out vec3 vDepth;        // mean depth at the center, depth slope per pixel (x, y)
flat out float vDepthSigma;
flat out int vOpen;          // 1: first slab of this splat, 2: last slab (open tails)

// Fills the flat outputs for splat number `n` of this draw; false when nothing is to be drawn.
bool setupSplat(uint n, out Footprint fp) {
  uint entry = order[(uSlabIndex >= 0 ? slabFirst[uSlabIndex] : uFirst) + n];
  if (!splatSetup(entry & kIndexMask, fp, vAmplitude, vColor, vValue)) return false;
  vCenter = fp.center;
  vConic = fp.conic;
  vDepth = vec3(fp.depth, fp.depthSlope);
  vDepthSigma = fp.depthSigma;
  vOpen = ((entry & kFirstSlab) != 0u ? 1 : 0) | ((entry & kLastSlab) != 0u ? 2 : 0);
  return true;
}

// True when this pass sums half of the slab (uPassHalf) and the kernel set up by setupSplat
// cannot reach it anywhere within `halfSide` pixels of its centre (its sprite or quad): every
// quarter share the fragment shader would take there is exactly 0.
bool missesPassHalf(Footprint fp, vec2 halfSide) {
  if (uPassHalf == 0 || !uSplitDepth) return false;
  bool openNear = uOpenTails && (vOpen & 1) != 0, openFar = uOpenTails && (vOpen & 2) != 0;
  float mid = 0.5 * (uSlabNear + uSlabFar);
  float zNear = uPassHalf == 1 ? (openNear ? -1e30 : uSlabNear) : mid;
  float zFar = uPassHalf == 1 ? mid : (openFar ? 1e30 : uSlabFar);
  float spread = dot(abs(fp.depthSlope), halfSide);
  return depthProfileMisses(fp.depth, spread, fp.depthSigma, zNear, zFar, uDepthProfile);
}

vec4 pixelToClip(vec2 pixel) {
  return vec4((pixel - uViewportRect.xy) / uViewportRect.zw * 2.0 - 1.0, uSlabMark, 1.0);
}
#endif  // SPLAT_COMPUTE
