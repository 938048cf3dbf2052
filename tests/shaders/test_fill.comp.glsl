// Test shader: fills a storage buffer with index * uScale so tests can check compute programs.
layout(local_size_x = 64) in;

layout(std430, binding = 0) buffer Values { float values[]; };

uniform float uScale;
uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < uCount) values[i] = float(i) * uScale;
}
