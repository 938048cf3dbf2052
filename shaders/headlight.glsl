// Phong shading with a head light: the mirror of headlightShade in src/core/shading.cpp.
uniform bool uShading;
uniform float uAmbient;
uniform float uDiffuse;
uniform float uSpecular;
uniform float uShininess;

vec3 headlightShade(vec3 rgb, vec3 normal, vec3 toEye) {
  if (!uShading || !(dot(normal, normal) > 0.0)) return rgb;
  float ndl = abs(dot(normal, toEye));
  return rgb * (uAmbient + uDiffuse * ndl) + vec3(uSpecular * pow(ndl, uShininess));
}
