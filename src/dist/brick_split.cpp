// The k-d brick split: prefix sums of block weights and the recursive cut.
#include "dist/brick_split.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ewa::dist {

int64_t VoxelBox::voxels() const {
  int64_t n = 1;
  for (int a = 0; a < 3; ++a) n *= std::max<int64_t>(0, high[a] - low[a]);
  return n;
}

VoxelWeights::VoxelWeights(std::array<int64_t, 3> dims) : dims_(dims) {}

VoxelWeights::VoxelWeights(std::array<int64_t, 3> dims, int64_t block,
                           const std::vector<double>& weights)
    : dims_(dims), block_(block) {
  if (block < 1) throw std::invalid_argument("VoxelWeights: block size must be at least 1");
  for (int a = 0; a < 3; ++a) blocks_[a] = (std::max<int64_t>(dims[a], 0) + block - 1) / block;
  const size_t count = size_t(blocks_[0] * blocks_[1] * blocks_[2]);
  if (weights.size() != count)
    throw std::invalid_argument("VoxelWeights: " + std::to_string(weights.size()) +
                                " block weights for " + std::to_string(count) + " blocks");
  const int64_t nx = blocks_[0] + 1, ny = blocks_[1] + 1, nz = blocks_[2] + 1;
  sums_.assign(size_t(nx * ny * nz), 0.0);
  auto at = [&](int64_t x, int64_t y, int64_t z) -> double& {
    return sums_[size_t(x + nx * (y + ny * z))];
  };
  for (int64_t z = 1; z < nz; ++z)
    for (int64_t y = 1; y < ny; ++y)
      for (int64_t x = 1; x < nx; ++x) {
        const double w = weights[size_t((x - 1) + blocks_[0] * ((y - 1) + blocks_[1] * (z - 1)))];
        if (!(w >= 0.0) || !std::isfinite(w))
          throw std::invalid_argument("VoxelWeights: a block weight is negative or not finite");
        at(x, y, z) = w + at(x - 1, y, z) + at(x, y - 1, z) + at(x, y, z - 1) -
                      at(x - 1, y - 1, z) - at(x - 1, y, z - 1) - at(x, y - 1, z - 1) +
                      at(x - 1, y - 1, z - 1);
      }
}

double VoxelWeights::prefix(int64_t x, int64_t y, int64_t z) const {
  const std::array<int64_t, 3> p{x, y, z};
  if (block_ == 0) return double(x) * double(y) * double(z);
  // Within a block the weight is spread evenly, so the prefix sum is multilinear there: the
  // block prefix sums interpolated at the fractional block coordinate.
  std::array<int64_t, 3> cell{};
  std::array<double, 3> t{};
  for (int a = 0; a < 3; ++a) {
    cell[a] = std::min(p[a] / block_, std::max<int64_t>(blocks_[a] - 1, 0));
    const int64_t start = cell[a] * block_;
    const int64_t length = std::min(block_, dims_[a] - start);
    t[a] = length > 0 ? double(p[a] - start) / double(length) : 0.0;
  }
  const int64_t nx = blocks_[0] + 1, ny = blocks_[1] + 1;
  double sum = 0.0;
  for (int c = 0; c < 8; ++c) {
    double w = 1.0;
    int64_t q[3];
    for (int a = 0; a < 3; ++a) {
      const bool up = (c >> a) & 1;
      q[a] = cell[a] + (up ? 1 : 0);
      w *= up ? t[a] : 1.0 - t[a];
    }
    if (w != 0.0) sum += w * sums_[size_t(q[0] + nx * (q[1] + ny * q[2]))];
  }
  return sum;
}

double VoxelWeights::weight(const VoxelBox& box) const {
  std::array<int64_t, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::clamp<int64_t>(box.low[a], 0, dims_[a]);
    hi[a] = std::clamp<int64_t>(box.high[a], 0, dims_[a]);
    if (hi[a] <= lo[a]) return 0.0;
  }
  return prefix(hi[0], hi[1], hi[2]) - prefix(lo[0], hi[1], hi[2]) - prefix(hi[0], lo[1], hi[2]) -
         prefix(hi[0], hi[1], lo[2]) + prefix(lo[0], lo[1], hi[2]) + prefix(lo[0], hi[1], lo[2]) +
         prefix(hi[0], lo[1], lo[2]) - prefix(lo[0], lo[1], lo[2]);
}

namespace {

// Splits `box` into `parts` bricks, appending them and the nodes; returns the child reference.
int splitBox(const VoxelWeights& weights, const VoxelBox& box, int parts, BrickSplit* out) {
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (box.size(a) > box.size(axis)) axis = a;
  if (parts == 1 || box.size(axis) < 2) {
    // One brick; a box too thin to cut gives its first brick all and the others nothing.
    const int first = int(out->bricks.size());
    out->bricks.push_back(box);
    for (int p = 1; p < parts; ++p) {
      VoxelBox empty = box;
      empty.low = empty.high;
      out->bricks.push_back(empty);
    }
    if (parts == 1) return -1 - first;
    // Chain the empty bricks behind the full one, so every brick sits in the tree.
    int child = -1 - int(out->bricks.size() - 1);
    for (int b = int(out->bricks.size()) - 2; b >= first; --b) {
      out->nodes.push_back({axis, box.high[axis], -1 - b, child});
      child = int(out->nodes.size()) - 1;
    }
    return child;
  }
  const int lowerParts = parts / 2;
  const VoxelWeights count(weights.dims());
  const VoxelWeights& by = weights.weight(box) > 0.0 ? weights : count;
  const double total = by.weight(box);
  const double target = total * double(lowerParts) / double(parts);
  // The plane whose lower weight is nearest the target, each side keeping a voxel layer; the
  // lower weight grows with the plane, so a binary search finds the crossing.
  int64_t lo = box.low[axis] + 1, hi = box.high[axis] - 1;
  auto lowerWeight = [&](int64_t plane) {
    VoxelBox lower = box;
    lower.high[axis] = plane;
    return by.weight(lower);
  };
  while (lo < hi) {
    const int64_t mid = lo + (hi - lo) / 2;
    if (lowerWeight(mid) < target)
      lo = mid + 1;
    else
      hi = mid;
  }
  int64_t plane = lo;
  if (plane > box.low[axis] + 1 &&
      std::abs(lowerWeight(plane - 1) - target) <= std::abs(lowerWeight(plane) - target))
    --plane;
  const int node = int(out->nodes.size());
  out->nodes.push_back({axis, plane, 0, 0});
  VoxelBox lower = box, upper = box;
  lower.high[axis] = plane;
  upper.low[axis] = plane;
  const int l = splitBox(weights, lower, lowerParts, out);
  const int u = splitBox(weights, upper, parts - lowerParts, out);
  out->nodes[size_t(node)].lower = l;
  out->nodes[size_t(node)].upper = u;
  return node;
}

}  // namespace

BrickSplit splitBricks(const VoxelWeights& weights, int parts) {
  if (parts < 1) throw std::invalid_argument("splitBricks: at least one brick");
  const auto& d = weights.dims();
  if (d[0] < 1 || d[1] < 1 || d[2] < 1)
    throw std::invalid_argument("splitBricks: the volume has no voxels");
  BrickSplit out;
  VoxelBox whole;
  whole.high = d;
  out.root = splitBox(weights, whole, parts, &out);
  return out;
}

}  // namespace ewa::dist
