// The composited volume over the background colour.
uniform sampler2D uImage;
uniform vec3 uBackground;

out vec4 outColor;

void main() {
  vec4 v = texelFetch(uImage, ivec2(gl_FragCoord.xy), 0);
  vec3 rgb = v.rgb + (1.0 - v.a) * uBackground;
  outColor = vec4(clamp(rgb, 0.0, 1.0), 1.0);
}
