// Ghost widths from the one kernel-reach formula, and the shared slab grid anchor.
#include "dist/brick_ghosts.h"

#include <algorithm>
#include <cmath>

#include "core/ewa_footprint.h"
#include "core/post_classification.h"

namespace ewa::dist {

namespace {

// Camera depth (-z) of each of the box's eight corners, by `f`.
template <typename F>
void forEachCornerDepth(const DataBox& box, const glm::dvec3& origin, const glm::dvec3& spacing,
                        const glm::dmat4& view, F f) {
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 index((c & 1) ? box.high.x : box.low.x, (c & 2) ? box.high.y : box.low.y,
                           (c & 4) ? box.high.z : box.low.z);
    const glm::dvec4 p = view * glm::dvec4(origin + index * spacing, 1.0);
    f(-p.z);
  }
}

}  // namespace

std::array<int64_t, 3> ghostVoxels(const GhostReach& g, const glm::dvec3& spacing) {
  const Classification& c = g.classification;
  const bool post = c.mode == ClassificationMode::Post;
  // A kernel drawn in the brick may be centred outside it by as far as it reaches.
  const double reach = worldReach(g.reach, std::max(g.farDepth, 0.0));
  // Post-classified, a voxel is kept when a visible voxel (or a crossing between 6-neighbours)
  // lies within the margin: its mark reads that far, and one voxel more.
  const int64_t margin =
      post ? int64_t(std::ceil(std::sqrt(double(c.postMarginSquared)) - 1e-9)) + 1 : 0;
  // The prefilter (its Laplacian), the gradient (central differences) and the surface test
  // (6-neighbours) read one voxel around each drawn voxel; the margin reads further around each
  // kept one, so the widest of them counts, not their sum.
  const int64_t prefilter = post && c.prefilter != 0.0 ? 1 : 0;
  const int64_t around = std::max<int64_t>({margin, prefilter, 1});
  std::array<int64_t, 3> out{};
  for (int a = 0; a < 3; ++a) {
    const int64_t kernel = int64_t(std::ceil(reach / spacing[a] - 1e-9));
    out[size_t(a)] = int64_t(std::max(g.stride, 1)) * (kernel + around);
  }
  return out;
}

double slabAnchorDepth(const DataBox& box, const glm::dvec3& origin, const glm::dmat4& view,
                       const DepthExtent& extent) {
  double nearest = INFINITY;
  forEachCornerDepth(box, origin, extent.spacing, view,
                     [&](double d) { nearest = std::min(nearest, d); });
  const glm::dvec3 sigma = kernelSigma(extent.spacing, extent.kernelWidth);
  const double variance = cameraCovariance(extent.rotation, sigma)[2][2];
  return nearest - depthReach(extent.reach, variance, nearest);
}

double farthestDepth(const DataBox& box, const glm::dvec3& origin, const glm::dvec3& spacing,
                     const glm::dmat4& view) {
  double farthest = -INFINITY;
  forEachCornerDepth(box, origin, spacing, view,
                     [&](double d) { farthest = std::max(farthest, d); });
  return farthest;
}

}  // namespace ewa::dist
