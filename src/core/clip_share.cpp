// Clipped shares of splat kernels along pixel rays (the C++ of shaders/clip_region.glsl).
#include "core/clip_share.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/ewa_footprint.h"
#include "core/footprint_formulas.h"

namespace ewa {

glm::dmat4 worldToVolumeFrame(const Volume& volume) {
  // x_frame = o + D^T (x - o)  (the inverse of x -> o + D (x - o)).
  const glm::dmat3 inverse = glm::transpose(volume.direction());
  const glm::dvec3& o = volume.origin();
  glm::dmat4 m(inverse);
  m[3] = glm::dvec4(o - inverse * o, 1.0);
  return m;
}

std::optional<DataBox> polytopeBounds(const DataBox& box, const std::vector<HalfSpace>& cuts) {
  // The box's faces as half-spaces, then the cuts: every corner of the polytope is where three
  // of these planes meet, on the kept side of all the others.
  std::vector<HalfSpace> all;
  for (int a = 0; a < 3; ++a) {
    glm::dvec3 n(0.0);
    n[a] = 1.0;
    all.push_back({n, -box.low[a]});
    all.push_back({-n, box.high[a]});
  }
  for (const HalfSpace& h : cuts)
    if (glm::length(h.normal) > 0.0)
      all.push_back({glm::normalize(h.normal), h.offset / glm::length(h.normal)});
  const double size = glm::length(box.high - box.low) + glm::length(box.low) + 1.0;
  const double tolerance = 1e-9 * size;
  glm::dvec3 lo(1e300), hi(-1e300);
  const size_t n = all.size();
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a + 1; b < n; ++b)
      for (size_t c = b + 1; c < n; ++c) {
        const glm::dvec3 bc = glm::cross(all[b].normal, all[c].normal);
        const double det = glm::dot(all[a].normal, bc);
        if (std::abs(det) < 1e-9) continue;  // two of them parallel, or all three on one line
        const glm::dvec3 x =
            -(all[a].offset * bc + all[b].offset * glm::cross(all[c].normal, all[a].normal) +
              all[c].offset * glm::cross(all[a].normal, all[b].normal)) /
            det;
        bool inside = true;
        for (const HalfSpace& h : all) inside = inside && h.distance(x) >= -tolerance;
        if (!inside) continue;
        lo = glm::min(lo, x);
        hi = glm::max(hi, x);
      }
  if (!(lo.x <= hi.x)) return std::nullopt;
  return DataBox{lo, hi};
}

DataBox keptBoxInVolumeFrame(const ClipRegion& region, const Volume& volume, double grow,
                             double outward) {
  const DataBox whole{volume.boundsMin() - grow, volume.boundsMax() + grow};
  if (!region.active()) return whole;
  std::vector<HalfSpace> cuts = halfSpacesInVolumeFrame(region, volume);
  for (HalfSpace& h : cuts) h.offset += outward;  // unit normals: moved out by `outward`
  const std::optional<DataBox> bounds = polytopeBounds(whole, cuts);
  if (!bounds) return whole;
  const glm::dvec3& sp = volume.spacing();
  const double hair = 1e-3 * std::min({sp.x, sp.y, sp.z});
  return DataBox{glm::max(bounds->low - hair, whole.low),
                 glm::min(bounds->high + hair, whole.high)};
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

RayInterval slabShareBounds(double zNear, double zFar, bool openNear, bool openFar,
                            const RayInterval& kept) {
  RayInterval bounds;
  slabShareBoundsOf(zNear, zFar, openNear, openFar, kept.near, kept.far, bounds.near, bounds.far);
  return bounds;
}

double clippedSlabFraction(double mu, double sigma, double zNear, double zFar, bool openNear,
                           bool openFar, const RayInterval& kept, const DepthProfile& profile) {
  const RayInterval bounds = slabShareBounds(zNear, zFar, openNear, openFar, kept);
  const double lo = bounds.near, hi = bounds.far;
  if (!(hi > lo)) return 0.0;
  return slabShareOf(mu, 1.0 / (std::sqrt(2.0) * sigma), lo, hi, profile.erfReach,
                     0.5 * profile.scale, usesErfSeries(profile));
}

bool clipCullsKernel(const std::vector<HalfSpace>& planes, const glm::dvec3& u, double reach) {
  for (const HalfSpace& h : planes)
    if (h.distance(u) < -reach) return true;
  return false;
}

}  // namespace ewa
