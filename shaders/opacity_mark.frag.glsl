// Early termination: marks in the stencil the pixels whose accumulated opacity reached the
// threshold (fragments that pass write it; an occlusion query counts them).
uniform sampler2D uAccum;
uniform float uThreshold;

out vec4 outColor;

void main() {
  if (texelFetch(uAccum, ivec2(gl_FragCoord.xy), 0).a < uThreshold) discard;
  outColor = vec4(0.0);
}
