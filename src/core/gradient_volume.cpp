// Packs the volume's gradient for the ray normals' 3D texture and reads it back as GL does.
#include "core/gradient_volume.h"

#include <algorithm>
#include <cmath>

#include "core/parallel_chunks.h"

namespace ewa {

namespace {

constexpr double kLevels = 1023.0;  // 10 bits

uint32_t packComponent(double c) {
  return uint32_t(std::lround(std::clamp(0.5 * (c + 1.0), 0.0, 1.0) * kLevels));
}

double unpackComponent(uint32_t bits) {
  return double(bits & 1023u) / kLevels * 2.0 - 1.0;
}

}  // namespace

PackedGradients packGradients(const Volume& volume, GradientMode mode, unsigned threads) {
  PackedGradients out;
  out.dims = volume.dims();
  const auto& d = out.dims;
  const glm::dvec3& spacing = volume.spacing();
  const size_t slices = size_t(d[2]), perSlice = size_t(d[0] * d[1]);
  const size_t minSlices = minItemsPerChunk(perSlice * 8);
  auto step = [&](int64_t i, int64_t j, int64_t k) {
    return volumeGradient(volume, i, j, k, mode) * spacing;  // per index step
  };
  // Two passes, the gradients found twice: a third list as big as the texels' (12 bytes a
  // voxel) would cost more than the second pass does.
  const std::vector<double> largest =
      parallelChunkResults<double>(slices, minSlices, threads, [&](size_t first, size_t last) {
        double most = 0.0;
        for (int64_t k = int64_t(first); k < int64_t(last); ++k)
          for (int64_t j = 0; j < d[1]; ++j)
            for (int64_t i = 0; i < d[0]; ++i) {
              const glm::dvec3 g = step(i, j, k);
              most = std::max({most, std::abs(g.x), std::abs(g.y), std::abs(g.z)});
            }
        return most;
      });
  const double most = largest.empty() ? 0.0 : *std::max_element(largest.begin(), largest.end());
  out.scale = most > 0.0 ? most : 1.0;
  out.texels.resize(slices * perSlice);
  const double inv = 1.0 / out.scale;
  parallelChunks(slices, minSlices, threads, [&](size_t first, size_t last, size_t) {
    for (int64_t k = int64_t(first); k < int64_t(last); ++k)
      for (int64_t j = 0; j < d[1]; ++j)
        for (int64_t i = 0; i < d[0]; ++i) {
          const glm::dvec3 g = step(i, j, k) * inv;
          out.texels[size_t(volume.index(i, j, k))] =
              packComponent(g.x) | packComponent(g.y) << 10 | packComponent(g.z) << 20;
        }
  });
  return out;
}

glm::dvec3 unpackGradient(uint32_t texel) {
  return {unpackComponent(texel), unpackComponent(texel >> 10), unpackComponent(texel >> 20)};
}

glm::dvec3 sampleGradient(const PackedGradients& gradients, const glm::dvec3& index) {
  const auto& d = gradients.dims;
  if (gradients.texels.empty()) return glm::dvec3(0.0);
  int64_t lo[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double x = std::clamp(index[a], 0.0, double(d[a] - 1));
    lo[a] = std::min<int64_t>(int64_t(std::floor(x)), d[a] - 1);
    f[a] = x - double(lo[a]);
  }
  glm::dvec3 sum(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    double w = 1.0;
    int64_t p[3];
    for (int a = 0; a < 3; ++a) {
      const bool high = (corner >> a) & 1;
      p[a] = std::min<int64_t>(lo[a] + (high ? 1 : 0), d[a] - 1);
      w *= high ? f[a] : 1.0 - f[a];
    }
    if (w == 0.0) continue;
    sum += w * unpackGradient(gradients.texels[size_t(p[0] + d[0] * (p[1] + d[1] * p[2]))]);
  }
  return sum;
}

}  // namespace ewa
