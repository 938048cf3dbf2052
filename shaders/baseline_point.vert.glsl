// Benchmark baseline: a bare point sprite at a precomputed pixel position and size.
layout(location = 0) in vec3 aPoint;  // pixel x, pixel y, point size
uniform vec2 uViewport;

void main() {
  gl_PointSize = aPoint.z;
  gl_Position = vec4(aPoint.xy / uViewport * 2.0 - 1.0, 0.0, 1.0);
}
