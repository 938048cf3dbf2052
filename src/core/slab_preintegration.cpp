// Pre-integration between slabs: texels from the shared table and their bilinear lookup.
#include "core/slab_preintegration.h"

#include <algorithm>
#include <cmath>

namespace ewa {

namespace {

// GL_LINEAR at coordinate (v (n - 1) + 0.5) / n: texel position v (n - 1), between the texels
// i0 and i1 on either side (clamped to the edge), t of the way to i1.
void linearTexels(double v, int n, int* i0, int* i1, double* t) {
  const double x = std::clamp(v, 0.0, 1.0) * double(n - 1);
  *i0 = std::min(int(std::floor(x)), n - 1);
  *i1 = std::min(*i0 + 1, n - 1);
  *t = x - double(*i0);
}

}  // namespace

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
  const int n = int(prefix.size());
  const auto at = [&](double x) {
    int i0, i1;
    double t;
    linearTexels(x, n, &i0, &i1, &t);
    return (1.0 - t) * double(prefix[size_t(i0)]) + t * double(prefix[size_t(i1)]);
  };
  const double mid = 0.5 * (front + back);
  const double half = 0.5 * std::max(std::abs(back - front), 1.0 / double(n - 1));
  const double a = std::clamp(mid - half, 0.0, 1.0), b = std::clamp(mid + half, 0.0, 1.0);
  return b > a ? std::max(0.0, (at(b) - at(a)) / (b - a)) : 0.0;
}

glm::dvec4 classifySlabPair(const std::vector<glm::vec4>& texels, int size,
                            const std::vector<float>& prefix, double front, double back,
                            double length) {
  int f0, f1, b0, b1;
  double tf, tb;
  linearTexels(front, size, &f0, &f1, &tf);
  linearTexels(back, size, &b0, &b1, &tb);
  const auto at = [&](int f, int b) { return glm::dvec4(texels[size_t(f) * size + b]); };
  const glm::dvec4 e = (1.0 - tf) * ((1.0 - tb) * at(f0, b0) + tb * at(f0, b1)) +
                       tf * ((1.0 - tb) * at(f1, b0) + tb * at(f1, b1));
  const double tau = segmentExtinction(prefix, front, back);
  const double alpha = -std::expm1(-std::max(0.0, length) * tau);
  return glm::dvec4(glm::dvec3(e) * alpha, alpha);
}

}  // namespace ewa
