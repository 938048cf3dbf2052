// The footprint's per-pixel formulas as templates of the float type: ewa_footprint.cpp's
// double functions are their double instances, the CPU splatter's per-pixel loop
// (core/tile_compositor.cpp) their float ones, as the shaders compute them in float.
#pragma once

#include <algorithm>
#include <cmath>

namespace ewa {

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
  const T x = std::clamp(t, -erfReach, erfReach);
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

// windowedGaussian: exp(-r/2) windowed by (1 - r/c)^2, 0 beyond the cutoff.
template <typename T>
inline T windowedGaussianOf(T r, T cutoff) {
  if (r > cutoff) return T(0);
  const T t = T(1) - r / cutoff;
  return std::exp(T(-0.5) * r) * t * t;
}

}  // namespace ewa
