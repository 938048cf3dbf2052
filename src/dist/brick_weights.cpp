// visibleBlockWeights: a brick's voxels that become splats, counted per block of the whole.
#include "dist/brick_weights.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/post_classification.h"

namespace ewa::dist {

std::vector<double> visibleBlockWeights(const Volume& volume, const std::array<int64_t, 3>& offset,
                                        const VoxelBox& brick, const std::array<int64_t, 3>& dims,
                                        int64_t block, const TransferFunction& tf,
                                        const Classification& classification) {
  if (block < 1) throw std::invalid_argument("visibleBlockWeights: block size must be at least 1");
  std::array<int64_t, 3> blocks{};
  for (size_t a = 0; a < 3; ++a) blocks[a] = (std::max<int64_t>(dims[a], 0) + block - 1) / block;
  std::vector<double> weights(size_t(blocks[0] * blocks[1] * blocks[2]), 0.0);
  if (brick.empty()) return weights;
  const auto& d = volume.dims();
  for (size_t a = 0; a < 3; ++a)
    if (brick.low[a] < offset[a] || brick.high[a] > offset[a] + d[a] || brick.low[a] < 0 ||
        brick.high[a] > dims[a])
      throw std::invalid_argument("visibleBlockWeights: the brick does not lie in the volume");
  // Opacity by value through a table over the value range, as classification looks it up, so
  // no search per voxel.
  constexpr int kTable = 4096;
  const double lo = volume.minValue(), hi = volume.maxValue();
  const double width = hi > lo ? hi - lo : 1.0;
  std::vector<uint8_t> visible(kTable);
  for (int t = 0; t < kTable; ++t)
    visible[size_t(t)] = tf.alphaAt(lo + width * t / (kTable - 1)) > 0.0;
  const auto isVisible = [&](double v) {
    if (!std::isfinite(v)) return false;
    return visible[size_t(
               std::clamp(int(std::lround((v - lo) / width * (kTable - 1))), 0, kTable - 1))] != 0;
  };
  std::vector<uint8_t> mask;
  const bool post = classification.mode == ClassificationMode::Post;
  if (post)
    mask = postClassificationMask(
        volume, [&](double v) { return isVisible(v); }, classification.postMarginSquared);
  for (int64_t z = brick.low[2]; z < brick.high[2]; ++z)
    for (int64_t y = brick.low[1]; y < brick.high[1]; ++y) {
      const size_t row = size_t((y / block) * blocks[0] + (z / block) * blocks[0] * blocks[1]);
      for (int64_t x = brick.low[0]; x < brick.high[0]; ++x) {
        const int64_t i = volume.index(x - offset[0], y - offset[1], z - offset[2]);
        const bool kept = post ? mask[size_t(i)] != 0 : isVisible(volume.valueAt(i));
        if (kept) weights[row + size_t(x / block)] += 1.0;
      }
    }
  return weights;
}

void addVoxelWeights(std::vector<double>& weights, const std::array<int64_t, 3>& dims,
                     int64_t block, double perVoxel) {
  std::array<int64_t, 3> blocks;
  for (size_t a = 0; a < 3; ++a) blocks[a] = (dims[a] + block - 1) / block;
  if (weights.size() != size_t(blocks[0] * blocks[1] * blocks[2]))
    throw std::invalid_argument("addVoxelWeights: " + std::to_string(weights.size()) +
                                " weights for " +
                                std::to_string(blocks[0] * blocks[1] * blocks[2]) + " blocks");
  // A block's extent along an axis: `block`, the last one cut short.
  const auto extent = [&](size_t a, int64_t b) { return std::min(block, dims[a] - b * block); };
  size_t at = 0;
  for (int64_t z = 0; z < blocks[2]; ++z)
    for (int64_t y = 0; y < blocks[1]; ++y)
      for (int64_t x = 0; x < blocks[0]; ++x, ++at)
        weights[at] += perVoxel * double(extent(0, x) * extent(1, y) * extent(2, z));
}

}  // namespace ewa::dist
