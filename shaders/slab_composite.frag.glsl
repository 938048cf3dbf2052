// Turns a slab's summed optical depth and light into premultiplied colour and opacity.
uniform sampler2D uSlab;

out vec4 outColor;

void main() {
  vec4 s = texelFetch(uSlab, ivec2(gl_FragCoord.xy), 0);
  float depth = max(s.a, 0.0);
  if (!(depth > 0.0)) discard;
  // Opacity 1 - exp(-depth), never the linearized sum, so dense slabs saturate at 1.
  float alpha = 1.0 - exp(-depth);
  vec3 color = s.rgb / depth;
  outColor = vec4(color * alpha, alpha);  // blended front to back: (1 - dst.a, 1)
}
