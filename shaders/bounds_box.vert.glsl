// The volume's bounding box as 12 triangles, for the occlusion query that stops the slab loop
// once every pixel it covers is opaque.
uniform mat4 uClip;  // world -> clip
uniform vec3 uBoxMin;
uniform vec3 uBoxMax;

const int kCorners[36] = int[36](0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3, 0, 4, 5, 0, 5, 1,
                                 2, 3, 7, 2, 7, 6, 0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5);

void main() {
  int c = kCorners[gl_VertexID];
  vec3 t = vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1));
  gl_Position = uClip * vec4(mix(uBoxMin, uBoxMax, t), 1.0);
}
