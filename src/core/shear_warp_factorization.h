// Shear-warp factorization of a parallel view: principal axis, per-slice shear and the 2D warp.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/camera.h"

namespace ewa {

// Lacroute's factorization M = W * S for the camera's viewing direction. Slices are normal to
// the principal axis (the one the ray, in voxel units, moves along fastest, so the shear per
// slice is at most one voxel); axisI and axisJ are the in-slice axes. Voxel (i, j) of slice k
// lands at intermediate-image position (i + offsetI(k), j + offsetJ(k)); intermediate pixel
// centres sit at integer (u, v), and warp maps them to output pixels (x right, y up, pixel
// centres at +0.5), the same pixel frame as the splat renderer.
struct ShearWarpFactorization {
  int principal = 2;
  int axisI = 0, axisJ = 1;
  int width = 0, height = 0, depth = 0;  // voxels along axisI, axisJ, principal
  bool increasing = true;                // slice 0 is the front slice
  double shearI = 0.0, shearJ = 0.0;     // intermediate offset per slice
  double translateI = 0.0, translateJ = 0.0;
  int imageWidth = 1, imageHeight = 1;  // intermediate image size
  double sliceSpacing = 1.0;            // world units between slices (d)
  double sampleRatio = 1.0;             // d'/d: distance between slices along a ray over d
  bool perspectiveAsParallel = false;   // the camera asked for perspective
  glm::dmat3 warp{1.0};                 // (u, v, 1) -> (x, y, 1)
  glm::dmat3 inverseWarp{1.0};

  double offsetI(int k) const { return shearI * k + translateI; }
  double offsetJ(int k) const { return shearJ * k + translateJ; }
  // The k-th slice in front-to-back order.
  int sliceAt(int step) const { return increasing ? step : depth - 1 - step; }
};

// Factorizes the view of a volume with `dims`, `spacing` and `origin` by `camera` into a
// width x height image. Parallel projection along the camera's direction; a perspective
// camera is drawn as the orthographic view of the same height at the focal point.
ShearWarpFactorization factorizeView(const Camera& camera, const std::array<int64_t, 3>& dims,
                                     const glm::dvec3& spacing, const glm::dvec3& origin, int width,
                                     int height);

}  // namespace ewa
