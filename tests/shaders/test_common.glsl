// Test snippet for tests/render/context_test.cpp: checks that #include and defines reach the shader.
#ifndef TEST_SCALE
#define TEST_SCALE 1.0
#endif

// The pixel centre in x/y, the colour's blue scaled by TEST_SCALE, and its alpha.
vec4 testValue(vec2 pixelCentre, vec4 color) {
  return vec4(pixelCentre, color.b * TEST_SCALE, color.a);
}
