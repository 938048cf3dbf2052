// GradientStencil: a volume's central differences, and their [1 2 1] average across each axis,
// by linear index through a reader of values; one stencil for the voxel normals
// (volumeGradient) and the ray normals' texels (packGradients).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

#include "core/splat_attributes.h"

namespace ewa {

// `Read`: double(int64_t linear index), NaN already read as 0.
template <typename Read>
class GradientStencil {
 public:
  // Differences are divided by the voxels they span times `unit` along their axis: the spacing
  // gives values per world unit, 1 per index step.
  GradientStencil(const std::array<int64_t, 3>& dims, const glm::dvec3& unit, Read read)
      : d_(dims), unit_(unit), read_(read) {}

  // The central difference along `axis` at voxel p, one-sided at the border, 0 on an axis one
  // voxel long.
  double central(const int64_t p[3], int axis) const {
    const int64_t stride = axis == 0 ? 1 : axis == 1 ? d_[0] : d_[0] * d_[1];
    const int64_t at = p[0] + d_[0] * (p[1] + d_[1] * p[2]);
    const int64_t behind = p[axis] > 0 ? 1 : 0, ahead = p[axis] < d_[axis] - 1 ? 1 : 0;
    if (behind + ahead == 0) return 0.0;
    return (read_(at + ahead * stride) - read_(at - behind * stride)) /
           (double(behind + ahead) * unit_[axis]);
  }

  // The gradient at voxel p: central differences, or for Smooth each axis's averaged over the
  // 3x3 neighbours across it with weights [1 2 1] x [1 2 1] / 16 (clamped at the border), which
  // damps noise in the normals.
  glm::dvec3 at(const int64_t p[3], GradientMode mode) const {
    glm::dvec3 g(0.0);
    for (int axis = 0; axis < 3; ++axis) {
      if (mode == GradientMode::Central) {
        g[axis] = central(p, axis);
        continue;
      }
      constexpr double w[3] = {0.25, 0.5, 0.25};
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      for (int s = -1; s <= 1; ++s)
        for (int t = -1; t <= 1; ++t) {
          int64_t q[3] = {p[0], p[1], p[2]};
          q[a1] = std::clamp<int64_t>(q[a1] + s, 0, d_[a1] - 1);
          q[a2] = std::clamp<int64_t>(q[a2] + t, 0, d_[a2] - 1);
          g[axis] += w[s + 1] * w[t + 1] * central(q, axis);
        }
    }
    return g;
  }

 private:
  std::array<int64_t, 3> d_;
  glm::dvec3 unit_;
  Read read_;
};

}  // namespace ewa
