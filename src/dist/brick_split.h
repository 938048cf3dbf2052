// BrickSplit: the voxel box cut into P bricks by a k-d split (longest axis first, any P),
// balanced by voxel count or by a weight per block of voxels (the visible voxels).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace ewa::dist {

// A box of voxel indices, half-open: low <= index < high on every axis. Empty when any
// high <= low.
struct VoxelBox {
  std::array<int64_t, 3> low{0, 0, 0};
  std::array<int64_t, 3> high{0, 0, 0};
  int64_t size(int axis) const { return high[axis] - low[axis]; }
  int64_t voxels() const;
  bool empty() const { return voxels() == 0; }
  bool operator==(const VoxelBox& o) const { return low == o.low && high == o.high; }
};

// What a split balances: the weight of a box of voxels. Voxel count by default; with
// blockWeights, the weight of each block of `block` voxels a side (x fastest, the last blocks
// along each axis cut short by the volume's end), spread evenly over the block's voxels, so a box
// that cuts a block takes its share of it by the voxels it holds.
class VoxelWeights {
 public:
  // Every voxel weighs 1.
  explicit VoxelWeights(std::array<int64_t, 3> dims);
  // Throws std::invalid_argument when `weights` is not one finite, non-negative value per block.
  VoxelWeights(std::array<int64_t, 3> dims, int64_t block, const std::vector<double>& weights);

  const std::array<int64_t, 3>& dims() const { return dims_; }
  // The weight of the voxels of `box` (clamped to the volume).
  double weight(const VoxelBox& box) const;

 private:
  // Weight of the voxels with index < (x, y, z) on each axis (x, y, z in 0..dims).
  double prefix(int64_t x, int64_t y, int64_t z) const;

  std::array<int64_t, 3> dims_{0, 0, 0};
  int64_t block_ = 0;  // 0: every voxel weighs 1
  std::array<int64_t, 3> blocks_{0, 0, 0};
  std::vector<double> sums_;  // (blocks + 1)^3 prefix sums of the block weights
};

// One cut of the k-d tree: voxels with index < plane along `axis` go to `lower`, the others to
// `upper`. A child is a node (>= 0) or a brick (-1 - brick index).
struct SplitNode {
  int axis = 0;
  int64_t plane = 0;
  int lower = -1;
  int upper = -1;
};

struct BrickSplit {
  std::vector<VoxelBox> bricks;  // brick b goes to rank b
  std::vector<SplitNode> nodes;
  int root = -1;  // the tree's top: a node (>= 0) or a brick (-1 - brick index)
};

// Splits the box of `weights.dims()` into `parts` bricks (at least 1): each node cuts its box
// across its longest axis (in voxels; the lowest such axis on a tie) at the plane that gives the
// lower child floor(parts / 2) / parts of the box's weight, as near as whole voxel planes allow,
// and each child at least one voxel layer while the axis has two. A box whose weight is 0 (no
// visible voxel) is cut by voxel count. Bricks are numbered in the
// tree's order (lower before upper). A box of one voxel cannot be cut: its extra bricks are
// empty. Throws std::invalid_argument for parts < 1 or a volume without voxels.
BrickSplit splitBricks(const VoxelWeights& weights, int parts);

}  // namespace ewa::dist
