// The volume's gradient as a 3D texture's texels: what shaded post-classified slabs sample along
// each pixel's ray (--post-normals ray), packed here and read back as the shader reads it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "core/splat_attributes.h"
#include "core/volume.h"

namespace ewa {

// One texel a voxel, x fastest: the gradient per index step (volumeGradient times the spacing,
// so the shader turns it into camera space with the camera-to-index matrix alone), divided by
// `scale`, the largest absolute component, and packed as GL_RGB10_A2 unorm with
// GL_UNSIGNED_INT_2_10_10_10_REV (red in the low bits): component c is stored as the 10-bit
// level 512 + round(511 c / scale), so zero is exact. Linear, so the texture's trilinear filter
// interpolates the gradient itself; the direction is all shading takes.
struct PackedGradients {
  std::array<int64_t, 3> dims{0, 0, 0};
  double scale = 1.0;
  std::vector<uint32_t> texels;
};

// The gradients of `volume` under `mode`, on `threads` threads (0: the machine's cores); the
// same for any thread count.
PackedGradients packGradients(const Volume& volume, GradientMode mode, unsigned threads = 0);

// 10 bits a component, zero at level 512 and +-1 at 1023 and 1: a zero gradient (uniform data)
// reads back as exactly zero, so it is drawn unshaded; with the levels' middle (511.5) for zero
// it read as 1/1023 in each component and lit uniform haze from a corner direction.
constexpr double kGradientZeroLevel = 512.0, kGradientSteps = 511.0;

// unpackGradientOf and sampleGradientOf are always inlined: the CPU splatter's AVX2 kernel calls
// them, and must keep no out-of-line copy that other callers could be linked to.
// One texel's gradient, relative to the largest component (each in [-1, 1]): the shader's
// decoding ((texel * 1023 - 512) / 511), in the float type T.
template <typename T>
__attribute__((always_inline)) inline glm::vec<3, T> unpackGradientOf(uint32_t texel) {
  const auto component = [](uint32_t bits) __attribute__((always_inline)) {
    return (T(bits & 1023u) - T(kGradientZeroLevel)) / T(kGradientSteps);
  };
  return {component(texel), component(texel >> 10), component(texel >> 20)};
}
glm::dvec3 unpackGradient(uint32_t texel);

// The texture read at index coordinates `index` (voxel centres at integers): trilinear between
// the eight nearest texels, clamped to the edge, as texture() samples it at (index + 0.5) /
// dims, in the float type T. The C++ mirror of rayGradient in shaders/slab_classify.glsl
// before its turn into camera space; the CPU splatter's ray normals take it in float.
template <typename T>
__attribute__((always_inline)) inline glm::vec<3, T> sampleGradientOf(
    const PackedGradients& gradients, const glm::vec<3, T>& index) {
  const auto& d = gradients.dims;
  if (gradients.texels.empty()) return glm::vec<3, T>(T(0));
  int64_t lo[3], hi[3];
  T f[3];
  for (int a = 0; a < 3; ++a) {
    const T x = std::clamp(index[a], T(0), T(d[a] - 1));
    lo[a] = std::min<int64_t>(int64_t(std::floor(x)), d[a] - 1);
    hi[a] = std::min<int64_t>(lo[a] + 1, d[a] - 1);
    f[a] = x - T(lo[a]);
  }
  const auto at = [&](int64_t x, int64_t y, int64_t z) __attribute__((always_inline)) {
    return unpackGradientOf<T>(gradients.texels[size_t(x + d[0] * (y + d[1] * z))]);
  };
  const auto along = [&](int64_t y, int64_t z) __attribute__((always_inline)) {  // across x
    return (T(1) - f[0]) * at(lo[0], y, z) + f[0] * at(hi[0], y, z);
  };
  const auto plane = [&](int64_t z) __attribute__((always_inline)) {  // across x and y
    return (T(1) - f[1]) * along(lo[1], z) + f[1] * along(hi[1], z);
  };
  return (T(1) - f[2]) * plane(lo[2]) + f[2] * plane(hi[2]);
}
glm::dvec3 sampleGradient(const PackedGradients& gradients, const glm::dvec3& index);

}  // namespace ewa
