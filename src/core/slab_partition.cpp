// SlabPartition: per-frame bucketing of splats into every image-aligned slab they reach.
#include "core/slab_partition.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/ewa_footprint.h"

namespace ewa {

double viewSpacing(const glm::dmat3& rotation, const glm::dvec3& spacing) {
  const double minSpacing = std::min({spacing.x, spacing.y, spacing.z});
  const double depth = std::sqrt(cameraCovariance(rotation, spacing)[2][2]);
  if (!(depth > minSpacing * (1.0 + 1e-9))) return minSpacing;
  const double steps = std::round(8.0 * std::log2(depth / minSpacing));
  return minSpacing * std::exp2(steps / 8.0);
}

double slabThicknessAlongView(double voxels, const glm::dmat3& rotation,
                              const glm::dvec3& spacing) {
  return std::max(0.25, voxels) * viewSpacing(rotation, spacing);
}

double slabGridStart(double front, double thickness, double anchor) {
  if (!std::isfinite(anchor) || !(thickness > 0.0)) return front;
  return anchor + std::floor((front - anchor) / thickness) * thickness;
}

namespace {

// Each splat's camera depth and depth variance, as the partition forms them: depth is affine in
// (i,j,k), depth = d0 + i*di + j*dj + k*dk, a surface splat's moved along its normal; a volume
// kernel's variance (W V'' W^T)_zz is the same for every voxel.
class KernelDepths {
 public:
  KernelDepths(const glm::dvec3& origin, const glm::dmat4& view, const DepthExtent& extent)
      : rotation_(extent.rotation),
        row_(-view[0][2], -view[1][2], -view[2][2]),
        sigma_(kernelSigma(extent.spacing, extent.kernelWidth)) {
    const glm::dvec3& spacing = extent.spacing;
    minSpacing_ = std::min({spacing.x, spacing.y, spacing.z});
    d0_ = glm::dot(row_, origin) - view[3][2];
    di_ = row_.x * spacing.x, dj_ = row_.y * spacing.y, dk_ = row_.z * spacing.z;
    volumeVariance_ = cameraCovariance(rotation_, sigma_)[2][2];
  }
  // A splat and its attributes (null: none, not a surface splat).
  void of(const PackedSplat& s, const PackedAttributes* attributes, double& depth,
          double& variance) const {
    depth = d0_ + SplatSet::i(s) * di_ + SplatSet::j(s) * dj_ + SplatSet::k(s) * dk_;
    variance = volumeVariance_;
    if (attributes && (attributes->nzKind >> 16) != 0) {
      const UnpackedAttributes a = unpackAttributes(*attributes);
      if (a.surface) {
        depth += glm::dot(row_, a.normal) * a.offset * minSpacing_;
        variance = surfaceCovariance(rotation_, sigma_, a.normal)[2][2];
      }
    }
  }

 private:
  glm::dmat3 rotation_;
  glm::dvec3 row_, sigma_;
  double minSpacing_ = 1.0, d0_ = 0.0, di_ = 0.0, dj_ = 0.0, dk_ = 0.0, volumeVariance_ = 0.0;
};

}  // namespace

double nearestKernelFront(const SplatSet& splats, const AttributeList& attributes,
                          const glm::dvec3& origin, const glm::dmat4& view, double nearCull,
                          const DepthExtent& extent, const std::function<bool(size_t)>& keep) {
  // The depth and reach of each splat exactly as build forms them.
  const auto& s = splats.splats();
  const size_t n = s.size();
  const KernelDepths depths(origin, view, extent);
  const bool surfaces = attributes.size() == n;
  double front = INFINITY;
  for (size_t m = 0; m < n; ++m) {
    if (keep && !keep(m)) continue;
    double d, variance;
    depths.of(s[m], surfaces ? &attributes[m] : nullptr, d, variance);
    if (!(d > nearCull)) continue;
    front = std::min(front, double(float(d - depthReach(extent.reach, variance, d))));
  }
  return front;
}

void SlabPartition::build(const SplatSet& splats, const AttributeList& attributes,
                          const glm::dvec3& origin, const glm::dmat4& view, double thickness,
                          double nearCull, const DepthExtent& extent) {
  order_.clear();
  slabs_.clear();
  splatCount_ = 0;
  const auto& s = splats.splats();
  const size_t n = s.size();
  if (n == 0 || !(thickness > 0.0)) return;
  const KernelDepths depths(origin, view, extent);
  const bool surfaces = attributes.size() == n;
  lo_.resize(n);
  hi_.resize(n);
  double lo = INFINITY, hi = -INFINITY;
  nearestCenter_ = INFINITY;
  for (size_t m = 0; m < n; ++m) {
    double d, variance;
    depths.of(s[m], surfaces ? &attributes[m] : nullptr, d, variance);
    if (!(d > nearCull)) {
      lo_[m] = NAN;
      continue;
    }
    nearestCenter_ = std::min(nearestCenter_, d);
    const double radius = depthReach(extent.reach, variance, d);
    lo_[m] = float(d - radius);
    hi_[m] = float(d + radius);
    lo = std::min(lo, double(lo_[m]));
    hi = std::max(hi, double(hi_[m]));
  }
  if (!(lo <= hi)) return;
  lo = slabGridStart(lo, thickness, extent.anchorDepth);
  // Cap the slab count so a tiny thickness on a deep scene cannot exhaust memory.
  const double count = std::min(std::floor((hi - lo) / thickness) + 1.0, 1.0e6);
  const auto slabCount = static_cast<size_t>(count);
  const double scale = count < 1.0e6 ? 1.0 / thickness : count / (hi - lo) * (1.0 - 1e-9);
  auto slabOf = [&](float d) {
    return std::min(slabCount - 1, static_cast<size_t>(std::max(0.0, (d - lo) * scale)));
  };
  bucket_.assign(slabCount + 1, 0);
  for (size_t m = 0; m < n; ++m) {
    if (std::isnan(lo_[m])) continue;
    ++splatCount_;
    for (size_t b = slabOf(lo_[m]), e = slabOf(hi_[m]); b <= e; ++b) bucket_[b + 1]++;
  }
  for (size_t b = 1; b <= slabCount; ++b) bucket_[b] += bucket_[b - 1];
  order_.resize(bucket_[slabCount]);
  std::vector<uint32_t> cursor(bucket_.begin(), bucket_.end() - 1);
  for (size_t m = 0; m < n; ++m) {
    if (std::isnan(lo_[m])) continue;
    const size_t b0 = slabOf(lo_[m]), b1 = slabOf(hi_[m]);
    for (size_t b = b0; b <= b1; ++b)
      order_[cursor[b]++] = uint32_t(m) | (b == b0 ? kFirstSlab : 0u) | (b == b1 ? kLastSlab : 0u);
  }
  for (size_t b = 0; b < slabCount; ++b) {
    const uint32_t c = bucket_[b + 1] - bucket_[b];
    if (c) slabs_.push_back({lo + b / scale, lo + (b + 1) / scale, bucket_[b], c});
  }
}

bool slabsAdjacent(const Slab& a, const Slab& b) {
  const double gap =
      std::min(std::abs(a.farDepth - b.nearDepth), std::abs(b.farDepth - a.nearDepth));
  return gap <= 1e-6 * std::max(a.farDepth - a.nearDepth, b.farDepth - b.nearDepth);
}

}  // namespace ewa
