// The visible-voxel weights of a split (src/dist/brick_weights.h): per block, the voxels that
// become splats, counted brick by brick from each brick's own read with ghosts; the sum over the
// bricks is the whole volume's, post-classified counts add the margin, and a split by them
// balances what is visible.
#include "dist/brick_weights.h"

#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>
#include <vector>

#include "core/volume_crop.h"

namespace ewa::dist {
namespace {

constexpr std::array<int64_t, 3> kDims{20, 12, 10};

// 0 everywhere but a slab x >= 15 of 200s and one voxel of 150 at (3, 4, 5).
Volume slabVolume() {
  std::vector<uint8_t> bytes(size_t(kDims[0] * kDims[1] * kDims[2]), 0);
  for (int64_t z = 0; z < kDims[2]; ++z)
    for (int64_t y = 0; y < kDims[1]; ++y)
      for (int64_t x = 15; x < kDims[0]; ++x)
        bytes[size_t(x + kDims[0] * (y + kDims[1] * z))] = 200;
  bytes[size_t(3 + kDims[0] * (4 + kDims[1] * 5))] = 150;
  return Volume(kDims, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, std::move(bytes));
}

// Transparent up to 100, opaque from 140 on.
TransferFunction rampAbove100() {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {100.0, 0.0}, {140.0, 1.0}, {255.0, 1.0}};
  return tf;
}

Classification mode(ClassificationMode m) {
  Classification c;
  c.mode = m;
  return c;
}

double sum(const std::vector<double>& w) {
  return std::accumulate(w.begin(), w.end(), 0.0);
}

VoxelBox whole() {
  VoxelBox box;
  box.high = kDims;
  return box;
}

TEST(BrickWeights, PreClassifiedCountsTheVisibleVoxelsOfEachBlock) {
  const Volume v = slabVolume();
  const std::vector<double> w = visibleBlockWeights(v, {0, 0, 0}, whole(), kDims, 8, rampAbove100(),
                                                    mode(ClassificationMode::Pre));
  ASSERT_EQ(w.size(), 3u * 2u * 2u);  // blocks of 8: 3 x 2 x 2, the last ones short
  std::vector<double> expected(w.size(), 0.0);
  for (int64_t z = 0; z < kDims[2]; ++z)
    for (int64_t y = 0; y < kDims[1]; ++y)
      for (int64_t x = 0; x < kDims[0]; ++x)
        if (v.value(x, y, z) > 100.0) expected[size_t(x / 8 + 3 * (y / 8 + 2 * (z / 8)))] += 1.0;
  EXPECT_EQ(w, expected);
  EXPECT_EQ(sum(w), 5.0 * 12.0 * 10.0 + 1.0);
  EXPECT_EQ(w[0 + 3 * (0 + 2 * 0)], 1.0);  // the lone voxel's block
}

TEST(BrickWeights, BricksReadWithGhostsAddUpToTheWhole) {
  const Volume v = slabVolume();
  for (ClassificationMode m : {ClassificationMode::Pre, ClassificationMode::Post}) {
    SCOPED_TRACE(classificationModeName(m));
    const std::vector<double> all =
        visibleBlockWeights(v, {0, 0, 0}, whole(), kDims, 8, rampAbove100(), mode(m));
    const BrickSplit split = splitBricks(VoxelWeights(kDims), 3);
    std::vector<double> added(all.size(), 0.0);
    for (const VoxelBox& brick : split.bricks) {
      // The brick with 3 ghost voxels, as a volume of its own with the whole's value range.
      VoxelRange range;
      std::array<int64_t, 3> offset{};
      for (size_t a = 0; a < 3; ++a) {
        range.low[a] = std::max<int64_t>(brick.low[a] - 3, 0);
        range.high[a] = std::min<int64_t>(brick.high[a] + 3, kDims[a]) - 1;
        offset[a] = range.low[a];
      }
      Volume part = cropVolume(v, range);
      part.setValueStatistics(v.minValue(), v.maxValue(), v.histogram());
      const std::vector<double> w =
          visibleBlockWeights(part, offset, brick, kDims, 8, rampAbove100(), mode(m));
      for (size_t b = 0; b < w.size(); ++b) added[b] += w[b];
    }
    EXPECT_EQ(added, all);
  }
}

TEST(BrickWeights, PostClassifiedAddsTheMarginBesideVisibleVoxels) {
  const Volume v = slabVolume();
  const double pre = sum(visibleBlockWeights(v, {0, 0, 0}, whole(), kDims, 8, rampAbove100(),
                                             mode(ClassificationMode::Pre)));
  const double post = sum(visibleBlockWeights(v, {0, 0, 0}, whole(), kDims, 8, rampAbove100(),
                                              mode(ClassificationMode::Post)));
  // At least the layer x = 14 before the slab and the lone voxel's 6 neighbours.
  EXPECT_GE(post, pre + 12.0 * 10.0 + 6.0);
}

TEST(BrickWeights, ASplitByThemBalancesTheVisibleVoxels) {
  const Volume v = slabVolume();
  const std::vector<double> w = visibleBlockWeights(v, {0, 0, 0}, whole(), kDims, 1, rampAbove100(),
                                                    mode(ClassificationMode::Pre));
  const BrickSplit split = splitBricks(VoxelWeights(kDims, 1, w), 2);
  // By voxels the cut is at x = 10 and one brick draws everything; by visible voxels both
  // bricks hold about half of the slab (cut across x, the longest axis, inside it).
  ASSERT_EQ(split.nodes.size(), 1u);
  EXPECT_EQ(split.nodes[0].axis, 0);
  EXPECT_GE(split.nodes[0].plane, 17);
  EXPECT_LE(split.nodes[0].plane, 18);
}

TEST(BrickWeights, NothingOutsideTheBrickAndRefusesABrickOutsideTheVolume) {
  const Volume v = slabVolume();
  VoxelBox left;
  left.high = {10, kDims[1], kDims[2]};
  const std::vector<double> w = visibleBlockWeights(v, {0, 0, 0}, left, kDims, 8, rampAbove100(),
                                                    mode(ClassificationMode::Pre));
  EXPECT_EQ(sum(w), 1.0);  // the lone voxel only
  EXPECT_EQ(sum(visibleBlockWeights(v, {0, 0, 0}, VoxelBox{}, kDims, 8, rampAbove100(),
                                    mode(ClassificationMode::Pre))),
            0.0);
  EXPECT_THROW(visibleBlockWeights(v, {1, 0, 0}, whole(), kDims, 8, rampAbove100(),
                                   mode(ClassificationMode::Pre)),
               std::invalid_argument);
}

TEST(BrickWeights, HiddenVoxelsAddTheirBlocksVoxelsAndBoundAnEmptyBrick) {
  // 20 x 9 x 8 voxels in blocks of 8: 3 x 2 x 1 blocks, the last along x 4 voxels, along y 1.
  const std::array<int64_t, 3> dims{20, 9, 8};
  std::vector<double> weights(6, 0.0);
  weights[0] = 100.0;  // the visible voxels all in the first block
  addVoxelWeights(weights, dims, 8, 0.5);
  const std::vector<double> expected{100.0 + 256.0, 256.0, 128.0, 32.0, 32.0, 16.0};
  EXPECT_EQ(weights, expected);
  EXPECT_DOUBLE_EQ(std::accumulate(weights.begin(), weights.end(), 0.0), 100.0 + 0.5 * 20 * 9 * 8);
  EXPECT_THROW(addVoxelWeights(weights, {20, 9, 9}, 8, 0.5), std::invalid_argument);

  // Split in two by them, the brick of empty space holds at most (1 + f / k) times an even share.
  std::vector<double> sparse(64, 0.0);
  sparse[0] = 8.0 * 8 * 8;  // one full block visible of 4 x 4 x 4 blocks
  addVoxelWeights(sparse, {32, 32, 32}, 8, kHiddenVoxelWeight);
  const BrickSplit split = splitBricks(VoxelWeights({32, 32, 32}, 8, sparse), 2);
  const double f = 512.0 / (32.0 * 32 * 32), even = 32.0 * 32 * 32 / 2;
  for (const VoxelBox& brick : split.bricks)
    EXPECT_LE(double(brick.voxels()), (1.0 + f / kHiddenVoxelWeight) * even + 1e-9);
}

}  // namespace
}  // namespace ewa::dist
