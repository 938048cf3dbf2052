// Pre-integration between slabs: texels from the shared table and their bilinear lookup.
#include "core/slab_preintegration.h"

#include <algorithm>
#include <cmath>

namespace ewa {

std::vector<glm::vec4> slabPairTexels(const PreintegrationTable& table,
                                      const TransferFunction& tf) {
  const int n = table.size();
  std::vector<glm::vec4> texels(size_t(n) * size_t(n));
  for (int f = 0; f < n; ++f)
    for (int b = 0; b < n; ++b) {
      const glm::vec4& e = table.at(f, b);
      const double middle = table.lo() + (table.hi() - table.lo()) * 0.5 * (f + b) / (n - 1);
      const glm::vec3 colour = e.a > 0.0f ? glm::vec3(e) / e.a : glm::vec3(tf.colorAt(middle));
      // Capped as the 1D table is (TransferFunction::bake): an extinction beyond float's range
      // (a tiny opacity unit distance) turned the shader's opacity into NaN, drawn black.
      const double tau = std::min(table.meanExtinction(f, b), kMaxBakedExtinction);
      texels[size_t(f) * n + b] = glm::vec4(colour, float(tau));
    }
  return texels;
}

std::vector<float> extinctionPrefix(const TransferFunction& tf, double lo, double hi, int n) {
  constexpr int kSub = 8;  // midpoint samples between two entries
  std::vector<float> prefix(size_t(std::max(n, 2)), 0.0f);
  const int m = int(prefix.size());
  const double step = 1.0 / double(m - 1);
  double sum = 0.0;
  for (int i = 1; i < m; ++i) {
    for (int q = 0; q < kSub; ++q) {
      const double x = (i - 1 + (q + 0.5) / kSub) * step;
      sum += std::min(tf.extinctionAt(lo + (hi - lo) * x), kMaxPrefixExtinction) * step / kSub;
    }
    prefix[size_t(i)] = float(sum);
  }
  return prefix;
}

double segmentExtinction(const std::vector<float>& prefix, double front, double back) {
  return segmentExtinctionOf(prefix.data(), int(prefix.size()), front, back);
}

glm::dvec4 classifySlabPair(const std::vector<glm::vec4>& texels, int size,
                            const std::vector<float>& prefix, double front, double back,
                            double length) {
  return classifySlabPairOf(texels.data(), size, prefix.data(), int(prefix.size()), front, back,
                            length);
}

}  // namespace ewa
