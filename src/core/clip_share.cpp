// Clipped shares of splat kernels along pixel rays (the C++ of shaders/clip_region.glsl).
#include "core/clip_share.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/ewa_footprint.h"

namespace ewa {

glm::dmat4 worldToVolumeFrame(const Volume& volume) {
  // x_frame = o + D^T (x - o)  (the inverse of x -> o + D (x - o)).
  const glm::dmat3 inverse = glm::transpose(volume.direction());
  const glm::dvec3& o = volume.origin();
  glm::dmat4 m(inverse);
  m[3] = glm::dvec4(o - inverse * o, 1.0);
  return m;
}

std::vector<HalfSpace> halfSpacesInVolumeFrame(const ClipRegion& region, const Volume& volume) {
  const glm::dmat4 toFrame = worldToVolumeFrame(volume);
  std::vector<HalfSpace> out = region.halfSpaces();
  for (HalfSpace& h : out) h = transformed(h, toFrame);
  return out;
}

RayInterval clippedDepths(const std::vector<HalfSpace>& planes, const Projection& proj,
                          const glm::dvec2& pixel) {
  RayInterval kept{-kClipUnbounded, kClipUnbounded};
  const glm::dvec2 q = pixel - proj.principal;
  for (const HalfSpace& h : planes) {
    // The ray's point at depth z: perspective z * (q / f, -1), orthographic (q / ppu, -z);
    // dot(n, x) + offset = a z + b.
    double a, b;
    if (proj.orthographic) {
      a = -h.normal.z;
      b = (h.normal.x * q.x + h.normal.y * q.y) / proj.pixelsPerUnit + h.offset;
    } else {
      a = (h.normal.x * q.x + h.normal.y * q.y) / proj.focalPixels - h.normal.z;
      b = h.offset;
    }
    if (a > 0.0)
      kept.near = std::max(kept.near, -b / a);
    else if (a < 0.0)
      kept.far = std::min(kept.far, -b / a);
    else if (b < 0.0)
      kept.far = -kClipUnbounded;  // parallel to the ray and outside: nothing kept
  }
  return kept;
}

double clippedSlabFraction(double mu, double sigma, double zNear, double zFar, bool openNear,
                           bool openFar, const RayInterval& kept, const DepthProfile& profile) {
  const double lo = openNear ? kept.near : std::max(zNear, kept.near);
  const double hi = openFar ? kept.far : std::min(zFar, kept.far);
  if (!(hi > lo)) return 0.0;
  const double s = 1.0 / (std::sqrt(2.0) * sigma);
  return 0.5 * profile.scale *
         (profileErf((hi - mu) * s, profile) - profileErf((lo - mu) * s, profile));
}

bool clipCullsKernel(const std::vector<HalfSpace>& planes, const glm::dvec3& u, double reach) {
  for (const HalfSpace& h : planes)
    if (h.distance(u) < -reach) return true;
  return false;
}

}  // namespace ewa
