// Pre-integration between slabs (post-classified splatting): the shared table as GPU texels,
// and the per-pixel classification of a pair of slab values that the slab shader mirrors.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/vec4.hpp>
#include <type_traits>
#include <vector>

#include "core/footprint_formulas.h"
#include "core/preintegration_table.h"
#include "core/transfer_function.h"

namespace ewa {

// Entries (front, back) row-major, table.size() squared: rgb the segment's colour per unit
// opacity at the table's distance (c / alpha: the colour with its self-attenuation), a its
// mean extinction per world unit. Unlike c and alpha these hold for any segment length, so
// one table serves every pixel's ray length and a slab's partial coverage at silhouettes.
// A transparent entry's colour is the transfer function's at the segment's middle value: its
// opacity comes from the finer extinction prefix (below), which may not be zero there.
std::vector<glm::vec4> slabPairTexels(const PreintegrationTable& table, const TransferFunction& tf);

// Entries of the extinction prefix: as fine as the 1D transfer texture. A segment's opacity
// comes from it, not from the pair table, whose 256 entries per axis smear a sharp transfer
// function in a narrow part of a wide value range (an MR volume's uint16 values: a step over
// one entry of 16 values made a brain's surface 7% darker than a ray caster's).
constexpr int kExtinctionPrefixSize = 4096;

// P[i]: the integral of the extinction per world unit over normalized values [0, i / (n - 1)]
// of [lo, hi] (in normalized units), the extinction capped at kMaxPrefixExtinction so that
// float differences of P stay meaningful (a segment that long is opaque either way).
constexpr double kMaxPrefixExtinction = 1e3;
std::vector<float> extinctionPrefix(const TransferFunction& tf, double lo, double hi, int n);

// Mean extinction per world unit of a segment whose normalized value runs linearly from
// `front` to `back`: (P(b) - P(f)) / (b - f) with P read linearly between its samples, over at
// least one sample's width about the middle, so equal ends give the extinction there.
double segmentExtinction(const std::vector<float>& prefix, double front, double back);

// Premultiplied (r, g, b, alpha) of a ray segment `length` world units long whose normalized
// value (0 = the table's lo, 1 = hi) runs from `front` to `back`: the colour from the texels
// read with bilinear filtering at texel centres, as a GL_LINEAR texture lookup does, then
// alpha = 1 - exp(-length * segmentExtinction(prefix, ...)), colour = rgb * alpha
// (slab_composite.frag.glsl).
glm::dvec4 classifySlabPair(const std::vector<glm::vec4>& texels, int size,
                            const std::vector<float>& prefix, double front, double back,
                            double length);

// The formulas above in the float type T over bare arrays: the double functions are their
// double instances, the CPU splatter's per-pixel classification their float ones. Always
// inlined: the CPU splatter's AVX2 kernel calls them, and must keep no out-of-line copy that
// other callers could be linked to (tile_composite_kernel.h).

// GL_LINEAR at coordinate (v (n - 1) + 0.5) / n: texel position v (n - 1), between texels i0
// and i1 on either side (clamped to the edge), t of the way to i1.
template <typename T>
__attribute__((always_inline)) inline void linearTexelsOf(T v, int n, int& i0, int& i1, T& t) {
  const T x = std::clamp(v, T(0), T(1)) * T(n - 1);
  i0 = std::min(int(x), n - 1);  // x >= 0: int() is floor
  i1 = std::min(i0 + 1, n - 1);
  t = x - T(i0);
}

template <typename T>
__attribute__((always_inline)) inline T segmentExtinctionOf(const float* prefix, int n, T front,
                                                            T back) {
  const auto at = [&](T x) __attribute__((always_inline)) {
    int i0, i1;
    T t;
    linearTexelsOf(x, n, i0, i1, t);
    return (T(1) - t) * T(prefix[i0]) + t * T(prefix[i1]);
  };
  const T mid = T(0.5) * (front + back);
  const T half = T(0.5) * std::max(std::abs(back - front), T(1) / T(n - 1));
  const T a = std::clamp(mid - half, T(0), T(1)), b = std::clamp(mid + half, T(0), T(1));
  return b > a ? std::max(T(0), (at(b) - at(a)) / (b - a)) : T(0);
}

// classifySlabPair: premultiplied (r, g, b, alpha); `texels` size x size, `prefix` n long.
template <typename T>
__attribute__((always_inline)) inline glm::vec<4, T> classifySlabPairOf(const glm::vec4* texels,
                                                                        int size,
                                                                        const float* prefix, int n,
                                                                        T front, T back, T length) {
  const T tau = segmentExtinctionOf(prefix, n, front, back);
  // Double: -expm1, exact for tiny opacities; float: 1 - exp as the shader takes it, by the
  // CPU splatter's polynomial exp (footprint_formulas.h) rather than a library call.
  const T depth = std::max(T(0), length) * tau;
  T alpha;
  if constexpr (std::is_same_v<T, float>)
    alpha = 1.0f - expOf(-depth);
  else
    alpha = -std::expm1(-depth);
  if (!(alpha > T(0))) return glm::vec<4, T>(T(0));  // the colour would be scaled by 0
  int f0, f1, b0, b1;
  T tf, tb;
  linearTexelsOf(front, size, f0, f1, tf);
  linearTexelsOf(back, size, b0, b1, tb);
  const auto at = [&](int f, int b) __attribute__((always_inline)) {
    return glm::vec<4, T>(texels[size_t(f) * size + b]);
  };
  const glm::vec<4, T> e = (T(1) - tf) * ((T(1) - tb) * at(f0, b0) + tb * at(f0, b1)) +
                           tf * ((T(1) - tb) * at(f1, b0) + tb * at(f1, b1));
  return glm::vec<4, T>(glm::vec<3, T>(e) * alpha, alpha);
}

}  // namespace ewa
