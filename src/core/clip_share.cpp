// Clipped shares of splat kernels along pixel rays (the C++ of shaders/clip_region.glsl).
#include "core/clip_share.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
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

DataBox keptBoxInVolumeFrame(const ClipRegion& region, const Volume& volume, double grow) {
  const DataBox whole{volume.boundsMin() - grow, volume.boundsMax() + grow};
  if (!region.cropEnabled) return whole;
  const glm::dmat4 toFrame = worldToVolumeFrame(volume);
  glm::dvec3 lo(1e300), hi(-1e300);
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 corner((c & 1) ? region.cropMax.x : region.cropMin.x,
                            (c & 2) ? region.cropMax.y : region.cropMin.y,
                            (c & 4) ? region.cropMax.z : region.cropMin.z);
    const glm::dvec3 p(toFrame * glm::dvec4(corner, 1.0));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3& sp = volume.spacing();
  const double hair = 1e-3 * std::min({sp.x, sp.y, sp.z});
  lo -= hair;
  hi += hair;
  const DataBox kept{glm::max(lo, whole.low), glm::min(hi, whole.high)};
  if (!(kept.low.x <= kept.high.x && kept.low.y <= kept.high.y && kept.low.z <= kept.high.z))
    return whole;
  return kept;
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
