// Shear-warp factorization of a parallel view: principal axis, per-slice shear and the 2D warp.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/shear_warp_settings.h"

namespace ewa {

// Lacroute's factorization M = W * S for the camera's viewing direction. Slices are normal to
// the principal axis (the one the ray, in voxel units, moves along fastest, so the shear per
// slice is at most one voxel); axisI and axisJ are the in-slice axes. Voxel (i, j) of slice k
// lands at intermediate-image position (scale(k) i + offsetI(k), scale(k) j + offsetJ(k));
// intermediate pixel centres sit at integer (u, v), and warp maps them to output pixels (x right,
// y up, pixel centres at +0.5), the same pixel frame as the splat renderer.
//
// Parallel views: one scale for every slice (`magnification`: the picture's pixels a voxel,
// between 1, Lacroute's, and the caller's most intermediate pixels a voxel, so that a close-up
// is not a magnified image of one sample a voxel), offsets linear in k (a shear), an affine
// warp. Perspective views
// (Lacroute's thesis, section 3.3): slice k is also scaled towards the eye's foot on it by
// scale(k) = referenceDistance / |k - eye.z|, so that every intermediate pixel is one ray
// through the eye, and the warp is projective. referenceDistance makes an intermediate pixel
// about a pixel of the picture along the view axis (at most the caller's most intermediate
// pixels a voxel on the focal point's slice, at least one a voxel on the front slice),
// and the intermediate image covers only where the slices and the picture's rays meet, so an
// eye inside the volume gets the picture's resolution, not one pixel a voxel of a slice a
// voxel away. Slices nearer the eye than one voxel along the principal axis, or behind it, are
// not drawn (the near plane).
struct ShearWarpFactorization {
  int principal = 2;
  int axisI = 0, axisJ = 1;
  int width = 0, height = 0, depth = 0;  // voxels along axisI, axisJ, principal
  bool increasing = true;                // slices are drawn in increasing k
  int frontSlice = 0;                    // the first slice drawn (the front one)
  int sliceCount = 0;                    // slices drawn, from frontSlice away from the eye
  double shearI = 0.0, shearJ = 0.0;     // parallel: intermediate offset per slice
  double translateI = 0.0, translateJ = 0.0;
  int imageWidth = 1, imageHeight = 1;  // intermediate image size
  double sliceSpacing = 1.0;            // world units between slices (d)
  double sampleRatio = 1.0;    // d'/d: parallel, distance between slices along a ray over d
  double magnification = 1.0;  // parallel: intermediate pixels a voxel
  bool perspective = false;
  bool perspectiveAsParallel = false;  // a perspective camera drawn as the parallel view
  // Perspective: the eye in slice coordinates (voxels along axisI, axisJ, principal) and the
  // scale of a slice one voxel from it along the principal axis (intermediate pixels a voxel).
  glm::dvec3 eye{0.0};
  double referenceDistance = 1.0;
  glm::dvec3 spacing{1.0};  // world units a voxel along axisI, axisJ, principal
  glm::dmat3 warp{1.0};     // (u, v, 1) -> (x, y, 1), projective for perspective views
  glm::dmat3 inverseWarp{1.0};

  double scale(int k) const {
    return perspective ? referenceDistance / std::abs(k - eye.z) : magnification;
  }
  // Slices are resampled at every intermediate pixel (scaled: perspective or magnified views)
  // rather than shifted with the same bilinear weights across a slice (Lacroute's parallel loop).
  bool resampled() const { return perspective || magnification != 1.0; }
  double offsetI(int k) const {
    return perspective ? translateI - scale(k) * eye.x : shearI * k + translateI;
  }
  double offsetJ(int k) const {
    return perspective ? translateJ - scale(k) * eye.y : shearJ * k + translateJ;
  }
  // The slice drawn at front-to-back step `step` (0 <= step < sliceCount).
  int sliceAt(int step) const { return increasing ? frontSlice + step : frontSlice - step; }
  // Perspective: d'/d along the ray through intermediate pixel (u, v) (the same for every slice).
  double rayRatio(double u, double v) const;
};

// Intermediate images of perspective views larger than this many pixels are drawn as the
// parallel view instead (a wide view from near or inside the volume, some of whose
// rays run back along the principal axis).
constexpr double kMaxPerspectiveIntermediatePixels = 64.0 * 1024 * 1024;

// Factorizes the view of a volume with `dims`, `spacing` and `origin` by `camera` into a
// width x height image: parallel or perspective as the camera is (perspectiveAsParallel: a
// perspective view whose intermediate image would be too large, drawn as the orthographic view of
// the same height at the focal point), with at most `maxPerVoxel` (>= 1) intermediate pixels a
// voxel where the picture is finer.
ShearWarpFactorization factorizeView(const Camera& camera, const std::array<int64_t, 3>& dims,
                                     const glm::dvec3& spacing, const glm::dvec3& origin, int width,
                                     int height, double maxPerVoxel = kMaxIntermediatePerVoxel);

}  // namespace ewa
