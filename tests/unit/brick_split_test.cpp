// The k-d brick split (src/dist/brick_split.h): bricks tile the voxel box without overlap, cut
// across the longest axis first, balanced by voxel count for any number of bricks, or by block
// weights (visible voxels); a box too small for its bricks leaves the extra ones empty.
#include "dist/brick_split.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace ewa::dist {
namespace {

// Every voxel in exactly one brick, and every brick reached once from the root.
void expectTiles(const BrickSplit& split, const std::array<int64_t, 3>& dims) {
  std::vector<int> owner(size_t(dims[0] * dims[1] * dims[2]), -1);
  for (size_t b = 0; b < split.bricks.size(); ++b) {
    const VoxelBox& box = split.bricks[b];
    if (box.empty()) continue;
    for (int64_t z = box.low[2]; z < box.high[2]; ++z)
      for (int64_t y = box.low[1]; y < box.high[1]; ++y)
        for (int64_t x = box.low[0]; x < box.high[0]; ++x) {
          int& o = owner[size_t(x + dims[0] * (y + dims[1] * z))];
          ASSERT_EQ(o, -1) << "voxel in two bricks";
          o = int(b);
        }
  }
  for (int o : owner) ASSERT_GE(o, 0) << "voxel in no brick";
  std::vector<int> seen(split.bricks.size(), 0);
  std::vector<int> stack{split.root};
  while (!stack.empty()) {
    const int c = stack.back();
    stack.pop_back();
    if (c < 0) {
      ++seen[size_t(-1 - c)];
      continue;
    }
    stack.push_back(split.nodes[size_t(c)].lower);
    stack.push_back(split.nodes[size_t(c)].upper);
  }
  for (int s : seen) EXPECT_EQ(s, 1);
}

TEST(BrickSplit, OneBrickIsTheWholeBox) {
  const BrickSplit split = splitBricks(VoxelWeights({5, 6, 7}), 1);
  ASSERT_EQ(split.bricks.size(), 1u);
  EXPECT_EQ(split.bricks[0].high, (std::array<int64_t, 3>{5, 6, 7}));
  EXPECT_EQ(split.root, -1);
  EXPECT_TRUE(split.nodes.empty());
}

TEST(BrickSplit, CutsTheLongestAxisFirst) {
  const BrickSplit split = splitBricks(VoxelWeights({20, 64, 30}), 2);
  ASSERT_EQ(split.nodes.size(), 1u);
  EXPECT_EQ(split.nodes[0].axis, 1);
  EXPECT_EQ(split.nodes[0].plane, 32);
  // Then the halves' longest axis: 30 (z) against 32 (y): y again.
  const BrickSplit four = splitBricks(VoxelWeights({20, 64, 30}), 4);
  EXPECT_EQ(four.nodes[0].axis, 1);
  EXPECT_EQ(four.nodes[1].axis, 1);
  EXPECT_EQ(four.nodes[1].plane, 16);
}

TEST(BrickSplit, AnyCountTilesTheBoxAndBalancesVoxels) {
  const std::array<int64_t, 3> dims{37, 29, 41};
  for (int parts = 1; parts <= 13; ++parts) {
    SCOPED_TRACE(parts);
    const BrickSplit split = splitBricks(VoxelWeights(dims), parts);
    ASSERT_EQ(split.bricks.size(), size_t(parts));
    EXPECT_EQ(split.nodes.size(), size_t(parts - 1));
    expectTiles(split, dims);
    const double mean = double(dims[0] * dims[1] * dims[2]) / parts;
    for (const VoxelBox& b : split.bricks) {
      // Whole voxel layers: each cut is off by at most half a layer of its box, and the cuts
      // above a brick add up; 15% holds for these sizes.
      EXPECT_NEAR(double(b.voxels()), mean, 0.15 * mean);
    }
  }
}

TEST(BrickSplit, BlockWeightsBalanceTheVisibleVoxels) {
  // 64 x 16 x 16 voxels in blocks of 8: only the first quarter along x is visible (weight 1 a
  // voxel), so two bricks cut at x = 8, not at the middle.
  const std::array<int64_t, 3> dims{64, 16, 16};
  std::vector<double> blocks(8 * 2 * 2, 0.0);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) blocks[size_t(x + 8 * (y + 2 * z))] = 512.0;
  const VoxelWeights weights(dims, 8, blocks);
  VoxelBox whole;
  whole.high = dims;
  EXPECT_DOUBLE_EQ(weights.weight(whole), 4 * 2 * 512.0);
  VoxelBox part = whole;
  part.high[0] = 4;  // half of the first blocks along x
  EXPECT_DOUBLE_EQ(weights.weight(part), 4 * 256.0);
  const BrickSplit split = splitBricks(weights, 2);
  ASSERT_EQ(split.nodes.size(), 1u);
  EXPECT_EQ(split.nodes[0].axis, 0);
  EXPECT_EQ(split.nodes[0].plane, 8);
  expectTiles(split, dims);
  // Three bricks: a third of the weight each, to a layer of 16 x 16 visible voxels (whole
  // voxel planes; the cut above a brick and its own each off by at most half a layer).
  const BrickSplit three = splitBricks(weights, 3);
  expectTiles(three, dims);
  for (const VoxelBox& b : three.bricks)
    EXPECT_NEAR(weights.weight(b), weights.weight(whole) / 3, 256.0);
}

TEST(BrickSplit, NothingVisibleFallsBackToVoxelCount) {
  const std::array<int64_t, 3> dims{16, 8, 8};
  const VoxelWeights none(dims, 4, std::vector<double>(4 * 2 * 2, 0.0));
  const BrickSplit split = splitBricks(none, 2);
  EXPECT_EQ(split.nodes[0].plane, 8);
}

TEST(BrickSplit, ShortBlocksAtTheEndWeighTheirVoxels) {
  // 10 voxels in blocks of 4: blocks of 4, 4 and 2 voxels, the last weighing as much as the
  // others: its voxels are twice as heavy.
  const VoxelWeights w({10, 1, 1}, 4, {4.0, 4.0, 4.0});
  VoxelBox box;
  box.low = {8, 0, 0};
  box.high = {9, 1, 1};
  EXPECT_DOUBLE_EQ(w.weight(box), 2.0);
  box.low = {3, 0, 0};
  box.high = {5, 1, 1};
  EXPECT_DOUBLE_EQ(w.weight(box), 2.0);
}

TEST(BrickSplit, MoreBricksThanVoxelsLeavesSomeEmpty) {
  const std::array<int64_t, 3> dims{2, 1, 1};
  const BrickSplit split = splitBricks(VoxelWeights(dims), 5);
  ASSERT_EQ(split.bricks.size(), 5u);
  expectTiles(split, dims);
  int full = 0;
  for (const VoxelBox& b : split.bricks) full += b.empty() ? 0 : 1;
  EXPECT_EQ(full, 2);
  const BrickSplit one = splitBricks(VoxelWeights({1, 1, 1}), 3);
  expectTiles(one, {1, 1, 1});
}

TEST(BrickSplit, RefusesNoBricksAndBadWeights) {
  EXPECT_THROW(splitBricks(VoxelWeights({4, 4, 4}), 0), std::invalid_argument);
  EXPECT_THROW(splitBricks(VoxelWeights({0, 4, 4}), 2), std::invalid_argument);
  EXPECT_THROW(VoxelWeights({4, 4, 4}, 2, {1.0}), std::invalid_argument);
  EXPECT_THROW(VoxelWeights({2, 2, 2}, 2, {-1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace ewa::dist
