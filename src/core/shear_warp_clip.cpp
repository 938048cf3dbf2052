// ShearWarpClip: world half-spaces in slice coordinates, and the kept cells of a slice row.
#include "core/shear_warp_clip.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include "core/clip_share.h"

namespace ewa {

ShearWarpClip::ShearWarpClip(const ClipRegion& region, const Volume& volume,
                             const ShearWarpFactorization& view) {
  const glm::dvec3& s = volume.spacing();
  const glm::dvec3& o = volume.origin();
  for (const HalfSpace& h : halfSpacesInVolumeFrame(region, volume)) {
    // Frame point o + s * ijk: dot(n * s, ijk) + dot(n, o) + offset >= 0.
    const glm::dvec3 a = h.normal * s;
    planes_.emplace_back(a[view.axisI], a[view.axisJ], a[view.principal], h.distance(o));
  }
}

void ShearWarpClip::keptCells(int k, int j, double fracI, double fracJ, int* first,
                              int* last) const {
  // Cell i samples x = i + fracI: the cells whose x lies in the kept span.
  double lo = -1e300, hi = 1e300;
  keptSpan(k, j + fracJ, &lo, &hi);
  if (lo > hi) {
    *last = *first;
    return;
  }
  const double from = std::ceil(lo - fracI), to = std::floor(hi - fracI) + 1.0;
  if (from > *first) *first = int(std::min(from, double(INT_MAX / 2)));
  if (to < *last) *last = int(std::max(to, double(INT_MIN / 2)));
}

void ShearWarpClip::keptSpan(int k, double y, double* lo, double* hi) const {
  for (const glm::dvec4& p : planes_) {
    const double c = p.y * y + p.z * k + p.w;  // p.x * x + c >= 0
    if (p.x > 0.0) {
      *lo = std::max(*lo, -c / p.x);
    } else if (p.x < 0.0) {
      *hi = std::min(*hi, -c / p.x);
    } else if (c < 0.0) {  // the whole row is cut away
      *lo = 1e300;
      *hi = -1e300;
    }
  }
}

}  // namespace ewa
