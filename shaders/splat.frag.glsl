// Splat fragment: optical depth g * |det J| * windowed Gaussian * the share of the kernel's ray
// integral inside this slab, and emitted colour, added up; or for MIP the value, maximized.
#include "ewa_footprint.glsl"
#include "clip_region.glsl"

// Pixels marked opaque in the stencil are skipped before the shader runs.
layout(early_fragment_tests) in;

uniform float uCutoff;
uniform int uMode;          // 0 sum of optical depth and light, 2 MIP
uniform bool uSplitDepth;   // composite: take only the share between the slab's planes
uniform bool uOpenTails;    // the first and last slab of a kernel take its tails
uniform float uSlabNear;
uniform float uSlabFar;

flat in vec2 vCenter;
flat in vec3 vConic;
flat in float vAmplitude;
flat in vec3 vColor;
flat in float vValue;
flat in vec3 vDepth;
flat in float vDepthSigma;
flat in int vOpen;

out vec4 outColor;  // (colour * optical depth, optical depth), blended additively in a slab

void main() {
  vec2 dx = gl_FragCoord.xy - vCenter;
  float r = vConic.x * dx.x * dx.x + 2.0 * vConic.y * dx.x * dx.y + vConic.z * dx.y * dx.y;
  if (r > uCutoff) discard;
  float w = windowedGaussian(r, uCutoff);
  float mu = vDepth.x + dot(vDepth.yz, dx);
  bool openNear = !uSplitDepth || (uOpenTails && (vOpen & 1) != 0);
  bool openFar = !uSplitDepth || (uOpenTails && (vOpen & 2) != 0);
  // Cropped or clipped: the slab's share of the kernel on the kept side, in one erf difference.
  if (uClipCount > 0)
    w *= clippedSlabFraction(mu, vDepthSigma, uSlabNear, uSlabFar, openNear, openFar,
                             clippedDepths(gl_FragCoord.xy));
  else if (uSplitDepth)
    w *= slabFraction(mu, vDepthSigma, uSlabNear, uSlabFar, openNear, openFar);
  if (uMode == 2) {
    outColor = vec4(vValue * w, 0.0, 0.0, 0.0);  // blended with GL_MAX
    return;
  }
  float depth = vAmplitude * w;
  outColor = vec4(vColor * depth, depth);
}
