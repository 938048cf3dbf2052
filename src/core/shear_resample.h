// Sheared grids (gantry tilt, skewed axes) resampled within each slice onto a rotation's grid.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/volume.h"
#include "core/volume_orientation.h"

namespace ewa {

// How a sheared grid becomes an upright one. With A = D diag(spacing) (voxel steps in world) and
// R = orthonormalized(D), T = R^T A is upper triangular: each slice k stays a plane of the new
// grid (at z = T22 k), only moved and skewed within it. So every new voxel is a bilinear sample
// of one old slice, never a blend of two, and the slices keep their own resolution.
struct ShearPlan {
  bool ok = false;
  std::string problem;  // why the grid is not resampled, when !ok
  std::array<int64_t, 3> dims{1, 1, 1};
  glm::dvec3 spacing{1.0};    // T's diagonal
  glm::dvec3 origin{0.0};     // of the new grid's first voxel, in world
  glm::dmat3 direction{1.0};  // R: a rotation (or a reflection, as D's handedness is)
  glm::dmat3 shape{1.0};      // T: old voxel index -> offset from the old origin, in R's frame
  glm::dvec3 low{0.0};        // the new first voxel's offset from the old origin, in R's frame
  double skewDegrees = 0.0;   // the largest angle between an axis of D and its axis of R
};

// The plan for `grid` (dims, spacing, origin, direction; bytes unused). Not ok when D is a
// rotation already, degenerate, or so sheared that the new grid would hold more than
// `maxGrowth` times the voxels (each slice spread over several times its width).
ShearPlan planShearResample(const OrientedGrid& grid, double maxGrowth = 4.0);

// The voxels of the new grid: old slice k sampled bilinearly where each new voxel of plane k
// falls in it, `fill` where it falls outside the slice (give or take a millionth of a voxel,
// for rounding). Integer types round to the nearest value; the result has plan.dims voxels of
// `type`.
std::vector<uint8_t> resampleShear(const ShearPlan& plan, const OrientedGrid& grid, ScalarType type,
                                   double fill, unsigned threads = 0);

// The smallest finite value of `count` voxels of `type` in `bytes` (0 when there is none): what
// the corners a sheared grid never covered are filled with.
double smallestValue(const std::vector<uint8_t>& bytes, ScalarType type);

}  // namespace ewa
