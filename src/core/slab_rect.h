// SlabRect: the screen rectangle the kernels of one image-aligned slab can draw into, so the
// slab's splat, composite and mark passes need not cover the whole image.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/kernel_reach.h"

namespace ewa {

// Pixels [x0, x1) x [y0, y1), y up as gl_FragCoord.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  long long area() const { return empty() ? 0 : (long long)(x1 - x0) * (y1 - y0); }
  // The smallest rectangle holding both (an empty one adds nothing).
  PixelRect unite(const PixelRect& o) const;
};

// The nearest and farthest camera depth of the corners of the box [lo, hi] (`view` maps its
// frame to camera space, which looks down -z).
struct DepthRange {
  double nearest = 0.0, farthest = 0.0;
};
DepthRange boxDepthRange(const glm::dmat4& view, const glm::dvec3& lo, const glm::dvec3& hi);

// A rectangle holding every pixel a kernel listed in the slab [nearDepth, farDepth] can draw,
// for kernels centred in the box [centersMin, centersMax] (in the frame `view` maps to camera
// space) and nearer than `cullDepth` culled: the centres a slab lists lie within a kernel's
// largest depth reach of it, so the box is cut to that depth range, projected, and grown by
// the largest footprint radius there (pixelReach) plus two pixels. Conservative, never exact;
// the whole image when the range comes near the eye plane, empty when it misses the box.
PixelRect slabPixelRect(const glm::dmat4& view, const Projection& proj, const KernelReach& reach,
                        const glm::dvec3& centersMin, const glm::dvec3& centersMax,
                        double nearDepth, double farDepth, double cullDepth);

}  // namespace ewa
