// Benchmark baseline: a trivial fragment, added up.
out vec4 outColor;

void main() { outColor = vec4(0.001); }
