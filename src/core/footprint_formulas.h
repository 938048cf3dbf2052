// The footprint's per-pixel formulas as templates of the float type: ewa_footprint.cpp's
// double functions are their double instances, the CPU splatter's per-pixel loop
// (core/tile_compositor.cpp) their float ones, as the shaders compute them in float.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace ewa {

// exp: std::exp in double (the reference's); in float a polynomial without a library call, so
// the CPU splatter's pixel loops vectorize (relative error below 3e-7 over float's range),
// always inlined so that its AVX2 kernel keeps no out-of-line copy (tile_composite_kernel.h).
inline double expOf(double x) {
  return std::exp(x);
}
__attribute__((always_inline)) inline float expOf(float x) {
  // 2^n 2^f with n = round(x log2 e), |f| <= 1/2; 2^f = e^(f ln 2) by its Taylor series. n is
  // rounded by adding 1.5 * 2^23 (the sum's low bits hold it), without a float-to-int conversion.
  constexpr float kRound = 12582912.0f;
  const float t = std::min(std::max(x, -87.0f), 88.0f) * 1.44269504f;
  const float shifted = t + kRound;
  const float n = shifted - kRound;
  const float g = (t - n) * 0.693147181f;
  const float p =
      1.0f +
      g * (1.0f + g * (0.5f + g * (1.0f / 6.0f + g * (1.0f / 24.0f +
                                                      g * (1.0f / 120.0f + g * (1.0f / 720.0f))))));
  int32_t bits;
  std::memcpy(&bits, &shifted, sizeof bits);
  bits = (bits - 0x4B400000 + 127) << 23;  // n's bits less the constant's, as 2^n's exponent
  float scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return p * scale;
}

// erfApprox (Abramowitz and Stegun 7.1.28): 1 - 1 / p(|x|)^16, no exp.
template <typename T>
inline T erfApproxOf(T x) {
  const T ax = std::abs(x);
  T p = T(1) +
        ax * (T(0.0705230784) +
              ax * (T(0.0422820123) +
                    ax * (T(0.0092705272) +
                          ax * (T(0.0001520143) + ax * (T(0.0002765672) + ax * T(0.0000430638))))));
  p *= p;  // p^2, p^4, p^8, p^16
  p *= p;
  p *= p;
  p *= p;
  const T y = T(1) - T(1) / p;
  return x < T(0) ? -y : y;
}

// erfSeries: erf on [-kErfSeriesReach, kErfSeriesReach] as an odd polynomial of degree 9.
template <typename T>
inline T erfSeriesOf(T x) {
  const T x2 = x * x;
  return x *
         (T(1.12837876) + x2 * (T(-0.37611182) +
                                x2 * (T(0.11269018) + x2 * (T(-0.02624959) + x2 * T(0.00407206)))));
}

// profileErf: erf of `t` clamped to the cut `erfReach`, by the series where `series`
// (usesErfSeries).
template <typename T>
inline T profileErfOf(T t, T erfReach, bool series) {
  const T x = std::min(std::max(t, -erfReach), erfReach);
  return series ? erfSeriesOf(x) : erfApproxOf(x);
}

// A kernel's share between depths lo and hi (clippedSlabFraction, slabFraction): the cut
// depth profile's erf difference, `toErf` = 1 / (sqrt(2) sigma) and `halfScale` half the
// profile's scale.
template <typename T>
inline T slabShareOf(T mu, T toErf, T lo, T hi, T erfReach, T halfScale, bool series) {
  return halfScale * (profileErfOf((hi - mu) * toErf, erfReach, series) -
                      profileErfOf((lo - mu) * toErf, erfReach, series));
}

// slabShareBounds: the depths a slab share integrates between, [zNear, zFar] inside the kept
// [keptNear, keptFar], an open bound (the kernel's tail) the kept one.
template <typename T>
inline void slabShareBoundsOf(T zNear, T zFar, bool openNear, bool openFar, T keptNear, T keptFar,
                              T& lo, T& hi) {
  lo = openNear ? keptNear : std::max(zNear, keptNear);
  hi = openFar ? keptFar : std::min(zFar, keptFar);
}

// windowedGaussian: exp(-r/2) windowed by (1 - r/c)^2, 0 beyond the cutoff.
template <typename T>
inline T windowedGaussianOf(T r, T cutoff) {
  // Computed (t clamped at 0 beyond the cutoff), then masked by a product, not a select, which
  // GCC may turn into a branch around the exp: the CPU splatter's pixel loops vectorize.
  // The reciprocal's product, not a quotient: a loop takes the reciprocal out and divides none.
  const T inside = std::min(r, cutoff);
  const T t = T(1) - inside * (T(1) / cutoff);
  const T w = expOf(T(-0.5) * inside) * t * t;
  return w * (r > cutoff ? T(0) : T(1));
}

}  // namespace ewa
