// Test shader: evaluates shaders/kernel_reach.glsl at sample (depth, depth variance) pairs so
// tests/render/kernel_reach_test.cpp can hold it equal to src/core/kernel_reach.cpp.
#include "kernel_reach.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Inputs { vec2 inputs[]; };  // depth, variance
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };

uniform float uCutoff;
uniform float uDepthCutoff;
uniform float uMaxSigma;
uniform float uSwanSpacing;
uniform bool uSwan;
uniform bool uOrthographic;
uniform float uFocalPixels;
uniform float uPixelsPerUnit;
uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  KernelReach k = KernelReach(uCutoff, uDepthCutoff, uMaxSigma, uSwanSpacing, uSwan, uOrthographic,
                              uFocalPixels, uPixelsPerUnit);
  float depth = inputs[i].x, variance = inputs[i].y;
  outputs[i] = vec4(worldPerPixel(k, depth), reachStretch(k, depth), worldReach(k, depth),
                    depthReach(k, variance, depth));
}
