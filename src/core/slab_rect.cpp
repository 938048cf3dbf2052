// SlabRect: a slab's screen rectangle from the volume box cut to the slab's depth range.
#include "core/slab_rect.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ewa {

PixelRect PixelRect::unite(const PixelRect& o) const {
  if (o.empty()) return *this;
  if (empty()) return o;
  return {std::min(x0, o.x0), std::min(y0, o.y0), std::max(x1, o.x1), std::max(y1, o.y1)};
}

DepthRange boxDepthRange(const glm::dmat4& view, const glm::dvec3& lo, const glm::dvec3& hi) {
  DepthRange range{INFINITY, -INFINITY};
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
    const double depth = -(view * glm::dvec4(p, 1.0)).z;
    range.nearest = std::min(range.nearest, depth);
    range.farthest = std::max(range.farthest, depth);
  }
  return range;
}

PixelRect slabPixelRect(const glm::dmat4& view, const Projection& proj, const KernelReach& reach,
                        const glm::dvec3& centersMin, const glm::dvec3& centersMax,
                        double nearDepth, double farDepth, double cullDepth) {
  const PixelRect whole{0, 0, proj.width, proj.height};
  glm::dvec3 corner[8];
  double boxFar = 0.0;
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p((c & 1) ? centersMax.x : centersMin.x, (c & 2) ? centersMax.y : centersMin.y,
                       (c & 4) ? centersMax.z : centersMin.z);
    corner[c] = glm::dvec3(view * glm::dvec4(p, 1.0));
    boxFar = std::max(boxFar, -corner[c].z);
  }
  // A kernel is listed in every slab its depth extent reaches: its centre lies at most its
  // depth reach (variance at most maxSigma^2, Swan's stretch largest at the far end) in front
  // of or behind the slab. A little more for the partition's float extents.
  const double reachD = depthReach(reach, reach.maxSigma * reach.maxSigma, boxFar) * 1.01 +
                        1e-6 * (std::abs(boxFar) + 1.0);
  const double lo = std::max(nearDepth - reachD, cullDepth), hi = farDepth + reachD;
  if (!(lo < hi)) return {};
  // The box cut to lo <= depth <= hi: corners inside, and where edges cross the two planes.
  std::vector<glm::dvec3> points;
  const auto depth = [](const glm::dvec3& u) { return -u.z; };
  for (int c = 0; c < 8; ++c)
    if (depth(corner[c]) >= lo && depth(corner[c]) <= hi) points.push_back(corner[c]);
  for (int c = 0; c < 8; ++c)
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (c & bit) continue;  // each edge once, from its lower corner
      const glm::dvec3 &a = corner[c], &b = corner[c | bit];
      for (double plane : {lo, hi}) {
        const double da = depth(a) - plane, db = depth(b) - plane;
        if ((da < 0.0) != (db < 0.0)) points.push_back(a + (b - a) * (da / (da - db)));
      }
    }
  if (points.empty()) return {};
  double nearest = INFINITY;
  glm::dvec2 pmin(INFINITY), pmax(-INFINITY);
  for (const glm::dvec3& u : points) {
    const double d = depth(u);
    nearest = std::min(nearest, d);
    const glm::dvec2 pixel = proj.orthographic
                                 ? proj.principal + glm::dvec2(u) * proj.pixelsPerUnit
                                 : proj.principal + glm::dvec2(u) * (proj.focalPixels / d);
    pmin = glm::min(pmin, pixel);
    pmax = glm::max(pmax, pixel);
  }
  if (!proj.orthographic && !(nearest > 0.0)) return whole;
  const double grow = pixelReach(reach, proj, nearest) + 2.0;
  const auto clampTo = [](double v, int n) { return int(std::clamp(v, 0.0, double(n))); };
  if (!std::isfinite(grow) || !std::isfinite(pmin.x + pmin.y + pmax.x + pmax.y)) return whole;
  PixelRect r{clampTo(std::floor(pmin.x - grow), proj.width),
              clampTo(std::floor(pmin.y - grow), proj.height),
              clampTo(std::ceil(pmax.x + grow), proj.width),
              clampTo(std::ceil(pmax.y + grow), proj.height)};
  return r;
}

}  // namespace ewa
