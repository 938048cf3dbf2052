// SplatSet: the voxels a transfer function leaves visible, packed for the GPU.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/default_init_allocator.h"
#include "core/volume.h"

namespace ewa {

// More voxels are visible than the limit given to SplatSet::build allows.
class SplatLimitError : public std::length_error {
 public:
  using std::length_error::length_error;
};

// 8 bytes a splat: voxel indices and the value quantized over the volume's range.
struct PackedSplat {
  uint32_t ij;      // i | j << 16
  uint32_t kValue;  // k | quantized value << 16 (0..65535 over [minValue, maxValue])
};

// Filled in whole by SplatSet::build's parallel join: not zeroed first on one thread.
using SplatList = std::vector<PackedSplat, DefaultInitAllocator<PackedSplat>>;

class SplatSet {
 public:
  // Keeps voxels whose value's opacity (by `isVisible`, called on a 4096-entry table over the
  // value range, not per voxel) is above zero. Throws std::invalid_argument if a dimension
  // exceeds 65535. `stride` > 1 keeps every stride-th voxel along each axis (a coarse level).
  // Throws SplatLimitError as soon as more than `maxSplats` voxels are kept, before the list
  // grows past that (the caller's memory or GPU buffer limit).
  // `alsoKeep(i, j, k, value)`, when given, is asked about voxels the table leaves out (surface
  // voxels are kept whatever their opacity) from several threads at once. `threads`: as
  // parallelChunks takes it (0: the machine's cores); the list is the same for any count.
  using VoxelPredicate = std::function<bool(int64_t, int64_t, int64_t, double)>;
  static SplatSet build(const Volume& volume, const std::function<bool(double)>& isVisible,
                        int stride = 1, const VoxelPredicate& alsoKeep = nullptr,
                        size_t maxSplats = SIZE_MAX, unsigned threads = 0);

  const SplatList& splats() const { return splats_; }
  size_t size() const { return splats_.size(); }
  int stride() const { return stride_; }

  static constexpr int kValueLevels = 65536;
  // Value in [0, 1] over the volume's range of a packed splat.
  static float normalizedValue(const PackedSplat& s) {
    return float(s.kValue >> 16) / float(kValueLevels - 1);
  }
  // Stores `x` in [0, 1] (clamped) as splat n's value, quantized as build() does.
  void setNormalizedValue(size_t n, double x);
  static uint32_t i(const PackedSplat& s) { return s.ij & 0xffffu; }
  static uint32_t j(const PackedSplat& s) { return s.ij >> 16; }
  static uint32_t k(const PackedSplat& s) { return s.kValue & 0xffffu; }

 private:
  static uint32_t quantize(double x) {  // x in [0, 1]
    return static_cast<uint32_t>(std::lround(x * (kValueLevels - 1)));
  }
  SplatList splats_;
  int stride_ = 1;
};

}  // namespace ewa
