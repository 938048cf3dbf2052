// The volume's gradient as a 3D texture's texels: what shaded post-classified slabs sample along
// each pixel's ray (--post-normals ray), packed here and read back as the shader reads it.
#pragma once

#include <array>
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

// One texel's gradient, relative to the largest component (each in [-1, 1]): the shader's
// decoding ((texel * 1023 - 512) / 511).
glm::dvec3 unpackGradient(uint32_t texel);

// The texture read at index coordinates `index` (voxel centres at integers): trilinear between
// the eight nearest texels, clamped to the edge, as texture() samples it at (index + 0.5) /
// dims. The C++ mirror of rayGradient in shaders/slab_classify.glsl before its turn into
// camera space.
glm::dvec3 sampleGradient(const PackedGradients& gradients, const glm::dvec3& index);

}  // namespace ewa
