// Field normals: the gradient of the reconstructed field across a post-classified slab, from the
// neighbouring pixels' values and the slab halves' values; the C++ of pixelDerivativeFrom and
// gradientFrom in shaders/slab_classify.glsl, which the CPU splatter's tiles take in float.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/camera.h"

namespace ewa {

// d(value)/d(pixel) from the values `span` pixels ahead and behind: central where both have
// kernels, else one-sided; none: 0.
template <typename T>
inline T pixelDerivativeOf(bool hasAhead, T ahead, bool hasBehind, T behind, T centre, T span) {
  if (hasAhead && hasBehind) return T(0.5) * (ahead - behind) / span;
  if (hasAhead) return (ahead - centre) / span;
  if (hasBehind) return (centre - behind) / span;
  return T(0);
}

// Changes of the value (in [0, 1]) smaller than this across a pixel and half a slab are the
// float sums' rounding (uniform data's field): no direction.
constexpr double kFlatChange = 1e-5;

// The gradient of the reconstructed field in camera space (x right, y up, z towards the eye)
// per world unit: across the view from `derivatives` (per pixel, x and y) at the slab's middle
// depth, along it from the front half's mean value to the back half's, half a slab apart. The
// halves' sums are (weight * value, weight) each; the slab lies between camera depths `zNear`
// and `zFar`. Zero (drawn unlit) where every change is rounding.
template <typename T>
inline glm::vec<3, T> fieldGradientOf(const glm::vec<2, T>& derivatives, T frontSum, T frontWeight,
                                      T backSum, T backWeight, T zNear, T zFar,
                                      const Projection& proj) {
  const T thickness = zFar - zNear;
  const T depth = T(0.5) * (zNear + zFar);
  const T pixelsPerUnit =
      proj.orthographic ? T(proj.pixelsPerUnit) : T(proj.focalPixels) / std::max(depth, T(1e-30));
  const bool front = frontWeight > T(0), back = backWeight > T(0);
  const T change = front && back ? backSum / backWeight - frontSum / frontWeight : T(0);
  const T largest =
      std::max(std::max(std::abs(derivatives.x), std::abs(derivatives.y)), std::abs(change));
  if (largest < T(kFlatChange)) return glm::vec<3, T>(T(0));
  return glm::vec<3, T>(derivatives * pixelsPerUnit, -change / (T(0.5) * thickness));
}

}  // namespace ewa
