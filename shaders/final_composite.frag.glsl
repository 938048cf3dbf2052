// The picture: the composited volume over the background, or the X-ray or MIP gray.
uniform sampler2D uImage;   // composite: premultiplied colour and opacity
uniform sampler2D uSlab;    // xray: summed optical depth in alpha; mip: maximum in red
uniform int uMode;          // 0 composite, 1 xray, 2 mip
uniform int uXRayMap;       // 0 exp(-scale * sum), 1 scale * sum
uniform float uXRayScale;
uniform vec3 uBackground;

out vec4 outColor;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 rgb;
  if (uMode == 1) {
    float sum = max(texelFetch(uSlab, p, 0).a, 0.0) * uXRayScale;
    rgb = vec3(uXRayMap == 0 ? exp(-sum) : sum);
  } else if (uMode == 2) {
    float m = texelFetch(uSlab, p, 0).r;
    rgb = m > 0.0 ? vec3(m) : uBackground;
  } else {
    vec4 v = texelFetch(uImage, p, 0);
    rgb = v.rgb + (1.0 - v.a) * uBackground;
  }
  outColor = vec4(clamp(rgb, 0.0, 1.0), 1.0);
}
