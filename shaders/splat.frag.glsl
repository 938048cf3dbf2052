// Splat fragment: optical depth g * |det J| * windowed Gaussian * the share of the kernel's ray
// integral inside this slab, and emitted colour, added up; or for MIP the value, maximized.
#include "splat_variant.glsl"
#include "ewa_footprint.glsl"
#include "clip_region.glsl"

// Pixels marked opaque in the stencil are skipped before the shader runs.
layout(early_fragment_tests) in;

uniform float uCutoff;
uniform bool uSplitDepth;   // composite: take only the share between the slab's planes
uniform bool uOpenTails;    // the first and last slab of a kernel take its tails
uniform float uSlabNear;
uniform float uSlabFar;
uniform vec2 uDepthProfile;  // the kernels' depth profile (DepthProfile)

flat in vec2 vCenter;
flat in vec3 vConic;
flat in float vAmplitude;
flat in vec3 vColor;
flat in float vValue;
flat in vec3 vDepth;
flat in float vDepthSigma;
flat in int vOpen;

// Blended additively in a slab. pre: (colour * optical depth, optical depth). post: (weight *
// value, 0, 0, weight) and (weight * normal, 0), the weight being the optical depth a unit
// extinction would give (world length of the ray the kernel covers); with halves (weight *
// value, weight) of the front half, then of the back half; in quarters those of the first two
// quarters, and of the last two in the third image.
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outBack;

// The shares of the slab's quarters (front to back), cropped or clipped: on the kept side.
vec4 quarterShares(float mu, bool openNear, bool openFar) {
  vec2 kept = kClip ? clippedDepths(gl_FragCoord.xy) : vec2(-kClipUnbounded, kClipUnbounded);
  return slabQuarters(mu, vDepthSigma, uSlabNear, uSlabFar, openNear, openFar, kept,
                      uDepthProfile);
}

void main() {
  vec2 dx = gl_FragCoord.xy - vCenter;
  float r = vConic.x * dx.x * dx.x + 2.0 * vConic.y * dx.x * dx.y + vConic.z * dx.y * dx.y;
  if (r > uCutoff) discard;
  float w = windowedGaussian(r, uCutoff);
  float mu = vDepth.x + dot(vDepth.yz, dx);
  bool openNear = !uSplitDepth || (uOpenTails && (vOpen & 1) != 0);
  bool openFar = !uSplitDepth || (uOpenTails && (vOpen & 2) != 0);
  // The slab's share of the kernel (cropped or clipped: on the kept side), in erf differences.
  vec4 parts = vec4(0.0);  // with kHalves: w of the front and back halves (kQuarters: quarters)
  if (kQuarters) {
    parts = w * quarterShares(mu, openNear, openFar);
    w = parts.x + parts.y + parts.z + parts.w;
  } else if (kHalves) {
    float mid = 0.5 * (uSlabNear + uSlabFar);
    if (kClip) {
      vec2 kept = clippedDepths(gl_FragCoord.xy);
      parts.xy = vec2(clippedSlabFraction(mu, vDepthSigma, uSlabNear, mid, openNear, false, kept,
                                          uDepthProfile),
                      clippedSlabFraction(mu, vDepthSigma, mid, uSlabFar, false, openFar, kept,
                                          uDepthProfile));
    } else {
      parts.xy =
          slabHalves(mu, vDepthSigma, uSlabNear, uSlabFar, openNear, openFar, uDepthProfile);
    }
    parts.xy *= w;
    w = parts.x + parts.y;
  } else if (kClip) {
    w *= clippedSlabFraction(mu, vDepthSigma, uSlabNear, uSlabFar, openNear, openFar,
                             clippedDepths(gl_FragCoord.xy), uDepthProfile);
  } else if (uSplitDepth) {
    w *= slabFraction(mu, vDepthSigma, uSlabNear, uSlabFar, openNear, openFar, uDepthProfile);
  }
  outBack = vec4(0.0);
  if (kMip) {
    outColor = vec4(vValue * w, 0.0, 0.0, 0.0);  // blended with GL_MAX
    outNormal = vec4(0.0);
    return;
  }
  float depth = vAmplitude * w;
  if (kPost) {
    vec4 d = vAmplitude * parts;
    outColor = kHalves ? vec4(vValue * d.x, d.x, vValue * d.y, d.y)
                       : vec4(vValue * depth, 0.0, 0.0, depth);
    if (kQuarters) outBack = vec4(vValue * d.z, d.z, vValue * d.w, d.w);
    outNormal = vec4(vColor * depth, 0.0);
    return;
  }
  outColor = vec4(vColor * depth, depth);
  outNormal = vec4(0.0);
}
