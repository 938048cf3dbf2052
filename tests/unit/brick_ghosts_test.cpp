// Ghost widths from the kernel-reach formula, and the shared slab grid anchor: bricks cut the
// slabs the whole volume's partition cuts.
#include "dist/brick_ghosts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <vector>

#include "core/post_classification.h"
#include "core/splat_set.h"

namespace ewa::dist {
namespace {

GhostReach orthographicReach(double cutoff, double kernelWidth, ClassificationMode mode) {
  Projection proj;
  proj.orthographic = true;
  proj.pixelsPerUnit = 1e3;  // pixels of a thousandth of a voxel
  GhostReach g;
  g.reach = kernelReach(proj, FilterMode::Ewa, cutoff, glm::dvec3(1.0), kernelWidth);
  g.farDepth = 100.0;
  g.classification.mode = mode;
  g.classification.postMarginSquared = postClassificationMarginSquared(cutoff, kernelWidth);
  return g;
}

TEST(BrickGhosts, TheKernelsReachPlusWhatItsClassificationReads) {
  // Cutoff 5, width 0.7 (the default): reach sqrt(5) * 0.7 = 1.57 voxels -> 2.
  // Pre-classified: one voxel more (gradients, the surface test).
  EXPECT_EQ(ghostVoxels(orthographicReach(5.0, 0.7, ClassificationMode::Pre), glm::dvec3(1.0)),
            (std::array<int64_t, 3>{3, 3, 3}));
  // Post: margin squared 2 -> radius 2, and one voxel for the crossing test.
  EXPECT_EQ(ghostVoxels(orthographicReach(5.0, 0.7, ClassificationMode::Post), glm::dvec3(1.0)),
            (std::array<int64_t, 3>{5, 5, 5}));
  // Cutoff 4, width 1 (the paper's): reach 2 and the low-pass filter's pixel (a kernel exactly
  // 2 voxels out still touches the brick) -> 3; margin squared 4 -> radius 2, and one more.
  EXPECT_EQ(ghostVoxels(orthographicReach(4.0, 1.0, ClassificationMode::Post), glm::dvec3(1.0)),
            (std::array<int64_t, 3>{6, 6, 6}));
  // A level of detail's stride scales it.
  GhostReach coarse = orthographicReach(5.0, 0.7, ClassificationMode::Pre);
  coarse.stride = 2;
  EXPECT_EQ(ghostVoxels(coarse, glm::dvec3(1.0)), (std::array<int64_t, 3>{6, 6, 6}));
}

TEST(BrickGhosts, AnisotropicSpacingAndWidePixelsWidenIt) {
  // The reach is in world units from the largest sigma: thin axes need more voxels.
  Projection proj;
  proj.orthographic = true;
  proj.pixelsPerUnit = 1e3;
  GhostReach g;
  g.reach = kernelReach(proj, FilterMode::Ewa, 4.0, glm::dvec3(1.0, 1.0, 2.0), 1.0);
  g.classification.mode = ClassificationMode::Pre;
  // sqrt(4) * (1.0 * 2 + 0.001) = 4.002 world units: 5 voxels along x and y, 3 along z; plus
  // one.
  EXPECT_EQ(ghostVoxels(g, glm::dvec3(1.0, 1.0, 2.0)), (std::array<int64_t, 3>{6, 6, 4}));
  // A pixel of 2 voxels (zoomed out) widens the low-pass filter's reach: sqrt(4) * (1 + 2) = 6.
  proj.pixelsPerUnit = 0.5;
  g.reach = kernelReach(proj, FilterMode::Ewa, 4.0, glm::dvec3(1.0), 1.0);
  EXPECT_EQ(ghostVoxels(g, glm::dvec3(1.0)), (std::array<int64_t, 3>{7, 7, 7}));
}

// A volume of n^3 voxels, every one a splat.
Volume cube(int n) {
  std::vector<uint8_t> bytes(size_t(n) * n * n);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = uint8_t(1 + i % 200);
  return Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, std::move(bytes));
}

std::set<long long> planesOf(const SlabPartition& part) {
  std::set<long long> planes;  // in 1e-6 units: equal planes compare equal
  for (const Slab& s : part.slabs()) planes.insert(std::llround(s.nearDepth * 1e6));
  return planes;
}

TEST(BrickGhosts, AnAnchoredBrickCutsTheWholesSlabs) {
  const Volume whole = cube(12);
  // Obliquely from the front, slabs 1.7 thick: a brick's own front is off the whole's grid.
  const glm::dmat4 view = glm::lookAt(glm::dvec3(30, 22, 40), glm::dvec3(5.5), glm::dvec3(0, 1, 0));
  DepthExtent extent;
  extent.rotation = glm::dmat3(view);
  const double anchor = slabAnchorDepth(whole.indexDataBox(), whole.origin(), view, extent);
  // The anchor lies in front of every kernel of the whole volume.
  SlabPartition free;
  free.build(SplatSet::build(whole, [](double) { return true; }), {}, whole.origin(), view, 1.7,
             0.0, extent);
  ASSERT_FALSE(free.slabs().empty());
  EXPECT_LE(anchor, free.slabs().front().nearDepth + 1e-9);
  extent.anchorDepth = anchor;
  SlabPartition all;
  all.build(SplatSet::build(whole, [](double) { return true; }), {}, whole.origin(), view, 1.7, 0.0,
            extent);
  // The far half (k >= 6) as a brick of its own, its origin where its voxels are.
  std::vector<uint8_t> bytes(whole.bytes().begin() + 6 * 144, whole.bytes().end());
  const Volume brick({12, 12, 6}, glm::dvec3(1.0), glm::dvec3(0, 0, 6), ScalarType::UInt8,
                     std::move(bytes));
  SlabPartition part;
  part.build(SplatSet::build(brick, [](double) { return true; }), {}, brick.origin(), view, 1.7,
             0.0, extent);
  const std::set<long long> wholePlanes = planesOf(all), brickPlanes = planesOf(part);
  ASSERT_FALSE(brickPlanes.empty());
  for (long long plane : brickPlanes) EXPECT_TRUE(wholePlanes.count(plane)) << plane * 1e-6;
  // Without the anchor the brick's grid starts at its own nearest kernel, off the whole's.
  extent.anchorDepth = NAN;
  part.build(SplatSet::build(brick, [](double) { return true; }), {}, brick.origin(), view, 1.7,
             0.0, extent);
  EXPECT_FALSE(wholePlanes.count(*planesOf(part).begin()));
}

}  // namespace
}  // namespace ewa::dist
