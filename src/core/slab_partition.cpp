// SlabPartition: per-frame depth bucketing of splats into view-aligned slabs.
#include "core/slab_partition.h"

#include <algorithm>
#include <cmath>

namespace ewa {

void SlabPartition::build(const SplatSet& splats, const glm::dvec3& origin,
                          const glm::dvec3& spacing, const glm::dmat4& view, double thickness,
                          double nearCull) {
  order_.clear();
  slabs_.clear();
  const auto& s = splats.splats();
  const size_t n = s.size();
  if (n == 0 || !(thickness > 0.0)) return;
  // Depth is affine in (i,j,k): depth = d0 + i*di + j*dj + k*dk.
  const glm::dvec3 row(-view[0][2], -view[1][2], -view[2][2]);
  const double d0 = glm::dot(row, origin) - view[3][2];
  const double di = row.x * spacing.x, dj = row.y * spacing.y, dk = row.z * spacing.z;
  depth_.resize(n);
  double lo = INFINITY, hi = -INFINITY;
  for (size_t m = 0; m < n; ++m) {
    const double d = d0 + SplatSet::i(s[m]) * di + SplatSet::j(s[m]) * dj + SplatSet::k(s[m]) * dk;
    depth_[m] = float(d);
    if (d > nearCull) {
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
  if (!(lo <= hi)) return;
  // Cap the slab count so a tiny thickness on a deep scene cannot exhaust memory.
  const double count = std::min(std::floor((hi - lo) / thickness) + 1.0, 1.0e6);
  const auto slabCount = static_cast<size_t>(count);
  const double scale = count < 1.0e6 ? 1.0 / thickness : count / (hi - lo) * (1.0 - 1e-9);
  bucket_.assign(slabCount + 1, 0);
  auto slabOf = [&](float d) {
    return std::min(slabCount - 1, static_cast<size_t>(std::max(0.0, (d - lo) * scale)));
  };
  for (size_t m = 0; m < n; ++m)
    if (depth_[m] > nearCull) bucket_[slabOf(depth_[m]) + 1]++;
  for (size_t b = 1; b <= slabCount; ++b) bucket_[b] += bucket_[b - 1];
  order_.resize(bucket_[slabCount]);
  std::vector<uint32_t> cursor(bucket_.begin(), bucket_.end() - 1);
  for (size_t m = 0; m < n; ++m)
    if (depth_[m] > nearCull) order_[cursor[slabOf(depth_[m])]++] = uint32_t(m);
  for (size_t b = 0; b < slabCount; ++b) {
    const uint32_t c = bucket_[b + 1] - bucket_[b];
    if (c) slabs_.push_back({lo + b / scale, bucket_[b], c});
  }
}

}  // namespace ewa
