// Packs the volume's gradient for the ray normals' 3D texture and reads it back as GL does.
#include "core/gradient_volume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "core/gradient_stencil.h"
#include "core/parallel_chunks.h"

namespace ewa {

namespace {

uint32_t packComponent(double c) {
  return uint32_t(kGradientZeroLevel +
                  double(std::lround(std::clamp(c, -1.0, 1.0) * kGradientSteps)));
}

// A volume's values by linear index as doubles, NaN read as 0, for one scalar type: no switch
// on the type per read, which the first shaded frame would wait for.
template <typename T>
struct Values {
  const uint8_t* bytes;
  double operator()(int64_t n) const {
    T v;
    std::memcpy(&v, bytes + size_t(n) * sizeof(T), sizeof(T));
    const double x = double(v);
    return std::isfinite(x) ? x : 0.0;
  }
};

// Calls fn(p) for every voxel p of slices [first, last) of a volume of `dims`, x fastest.
template <typename Fn>
void forSlices(const std::array<int64_t, 3>& d, size_t first, size_t last, Fn fn) {
  for (int64_t p[3] = {0, 0, int64_t(first)}; p[2] < int64_t(last); ++p[2])
    for (p[1] = 0; p[1] < d[1]; ++p[1])
      for (p[0] = 0; p[0] < d[0]; ++p[0]) fn(p);
}

template <typename Read>
void packWith(const Volume& volume, Read read, GradientMode mode, unsigned threads,
              PackedGradients& out) {
  // volumeGradient's stencil per index step (the shader turns it into camera space).
  const GradientStencil<Read> steps(volume.dims(), glm::dvec3(1.0), read);
  const auto& d = out.dims;
  const size_t slices = size_t(d[2]), perSlice = size_t(d[0] * d[1]);
  const size_t minSlices = minItemsPerChunk(perSlice * 8);
  // Two passes: the scale from the central differences (a Smooth gradient averages them, so
  // they bound it), then the texels. A list of the gradients between them would take 12 bytes
  // a voxel.
  const std::vector<double> largest =
      parallelChunkResults<double>(slices, minSlices, threads, [&](size_t first, size_t last) {
        double most = 0.0;
        forSlices(d, first, last, [&](const int64_t p[3]) {
          for (int axis = 0; axis < 3; ++axis)
            most = std::max(most, std::abs(steps.central(p, axis)));
        });
        return most;
      });
  const double most = largest.empty() ? 0.0 : *std::max_element(largest.begin(), largest.end());
  out.scale = most > 0.0 ? most : 1.0;
  out.texels.resize(slices * perSlice);
  const double inv = 1.0 / out.scale;
  parallelChunks(slices, minSlices, threads, [&](size_t first, size_t last, size_t) {
    forSlices(d, first, last, [&](const int64_t p[3]) {
      const glm::dvec3 g = steps.at(p, mode) * inv;
      out.texels[size_t(volume.index(p[0], p[1], p[2]))] =
          packComponent(g.x) | packComponent(g.y) << 10 | packComponent(g.z) << 20;
    });
  });
}

}  // namespace

PackedGradients packGradients(const Volume& volume, GradientMode mode, unsigned threads) {
  PackedGradients out;
  out.dims = volume.dims();
  const uint8_t* bytes = volume.bytes().data();
  switch (volume.type()) {
    case ScalarType::UInt8:
      packWith(volume, Values<uint8_t>{bytes}, mode, threads, out);
      break;
    case ScalarType::Int16:
      packWith(volume, Values<int16_t>{bytes}, mode, threads, out);
      break;
    case ScalarType::UInt16:
      packWith(volume, Values<uint16_t>{bytes}, mode, threads, out);
      break;
    case ScalarType::Float32:
      packWith(volume, Values<float>{bytes}, mode, threads, out);
      break;
  }
  return out;
}

glm::dvec3 unpackGradient(uint32_t texel) {
  return unpackGradientOf<double>(texel);
}

glm::dvec3 sampleGradient(const PackedGradients& gradients, const glm::dvec3& index) {
  return sampleGradientOf(gradients, index);
}

}  // namespace ewa
