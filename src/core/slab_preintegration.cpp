// Pre-integration between slabs: texels from the shared table and their bilinear lookup.
#include "core/slab_preintegration.h"

#include <algorithm>
#include <cmath>

namespace ewa {

std::vector<glm::vec4> slabPairTexels(const PreintegrationTable& table) {
  const int n = table.size();
  std::vector<glm::vec4> texels(size_t(n) * size_t(n));
  for (int f = 0; f < n; ++f)
    for (int b = 0; b < n; ++b) {
      const glm::vec4& e = table.at(f, b);
      const glm::vec3 colour = e.a > 0.0f ? glm::vec3(e) / e.a : glm::vec3(0.0f);
      // Capped as the 1D table is (TransferFunction::bake): an extinction beyond float's range
      // (a tiny opacity unit distance) turned the shader's opacity into NaN, drawn black.
      const double tau = std::min(table.meanExtinction(f, b), kMaxBakedExtinction);
      texels[size_t(f) * n + b] = glm::vec4(colour, float(tau));
    }
  return texels;
}

glm::dvec4 classifySlabPair(const std::vector<glm::vec4>& texels, int size, double front,
                            double back, double length) {
  // GL_LINEAR at coordinate (v (n - 1) + 0.5) / n: texel position v (n - 1), between the
  // texels on either side (clamped to the edge).
  const auto split = [size](double v, int* i0, int* i1, double* t) {
    const double x = std::clamp(v, 0.0, 1.0) * double(size - 1);
    *i0 = std::min(int(std::floor(x)), size - 1);
    *i1 = std::min(*i0 + 1, size - 1);
    *t = x - double(*i0);
  };
  int f0, f1, b0, b1;
  double tf, tb;
  split(front, &f0, &f1, &tf);
  split(back, &b0, &b1, &tb);
  const auto at = [&](int f, int b) { return glm::dvec4(texels[size_t(f) * size + b]); };
  const glm::dvec4 e = (1.0 - tf) * ((1.0 - tb) * at(f0, b0) + tb * at(f0, b1)) +
                       tf * ((1.0 - tb) * at(f1, b0) + tb * at(f1, b1));
  const double alpha = -std::expm1(-std::max(0.0, length) * e.a);
  return glm::dvec4(glm::dvec3(e) * alpha, alpha);
}

}  // namespace ewa
