// A triangle covering the viewport, for image-space passes.
out vec2 vUv;
uniform float uSlabMark;  // clip-space z (the slab pass: its slab's mark)

void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  vUv = p;
  gl_Position = vec4(p * 2.0 - 1.0, uSlabMark, 1.0);
}
