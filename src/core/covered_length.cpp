// Post-classified slabs' covered length, ended at the data's box.
#include "core/covered_length.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>

#include "core/camera.h"

namespace ewa {

glm::dmat4 cameraToIndex(const Volume& volume, const Camera& volumeCamera) {
  glm::dmat4 toIndex(1.0);  // the volume's frame to index coordinates
  for (int axis = 0; axis < 3; ++axis) {
    toIndex[axis][axis] = 1.0 / volume.spacing()[axis];
    toIndex[3][axis] = -volume.origin()[axis] / volume.spacing()[axis];
  }
  return toIndex * glm::inverse(volumeCamera.viewMatrix());
}

IndexRay indexRay(const glm::dmat4& toIndex, const Projection& proj, const glm::dvec2& pixel) {
  // The camera-space point at depth z: perspective z * (q / f, -1), orthographic (q / ppu, -z).
  const glm::dvec2 q =
      (pixel - proj.principal) / (proj.orthographic ? proj.pixelsPerUnit : proj.focalPixels);
  const glm::dvec3 origin = proj.orthographic ? glm::dvec3(q, 0.0) : glm::dvec3(0.0);
  const glm::dvec3 direction = proj.orthographic ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(q, -1.0);
  return {glm::dvec3(toIndex * glm::dvec4(origin, 1.0)), glm::dmat3(toIndex) * direction};
}

double rayStretch(const Projection& proj, const glm::dvec2& pixel) {
  if (proj.orthographic) return 1.0;
  const glm::dvec2 q = (pixel - proj.principal) / proj.focalPixels;
  return std::sqrt(1.0 + glm::dot(q, q));
}

RayInterval boxDepths(const glm::dvec3& origin, const glm::dvec3& direction, const DataBox& box) {
  RayInterval kept{-1e300, 1e300};
  for (int axis = 0; axis < 3; ++axis) {
    const double d = direction[axis];
    const double inv = 1.0 / (std::abs(d) < 1e-30 ? 1e-30 : d);
    const double t0 = (box.low[axis] - origin[axis]) * inv;
    const double t1 = (box.high[axis] - origin[axis]) * inv;
    kept.near = std::max(kept.near, std::min(t0, t1));
    kept.far = std::min(kept.far, std::max(t0, t1));
  }
  return kept;
}

double coveredLength(double a, double b, const RayInterval& inBox, double stretch, double weight) {
  return coveredLengthOf(a, b, inBox.near, inBox.far, stretch, weight);
}

}  // namespace ewa
