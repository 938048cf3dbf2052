// Splat fragment: optical depth g * |det J| * windowed Gaussian, and emitted colour, added up.
#include "ewa_footprint.glsl"

uniform float uCutoff;

flat in vec2 vCenter;
flat in vec3 vConic;
flat in float vAmplitude;
flat in vec3 vColor;

out vec4 outColor;  // (colour * optical depth, optical depth), blended additively in a slab

void main() {
  vec2 dx = gl_FragCoord.xy - vCenter;
  float r = vConic.x * dx.x * dx.x + 2.0 * vConic.y * dx.x * dx.y + vConic.z * dx.y * dx.y;
  if (r > uCutoff) discard;
  float depth = vAmplitude * windowedGaussian(r, uCutoff);
  outColor = vec4(vColor * depth, depth);
}
