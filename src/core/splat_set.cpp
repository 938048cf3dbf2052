// SplatSet: classification of voxels into splats through a visibility table.
#include "core/splat_set.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ewa {

SplatSet SplatSet::build(const Volume& volume, const std::function<bool(double)>& isVisible,
                         int stride, const VoxelPredicate& alsoKeep, size_t maxSplats) {
  SplatSet set;
  set.stride_ = std::max(1, stride);
  const auto& d = volume.dims();
  if (d[0] > 65535 || d[1] > 65535 || d[2] > 65535)
    throw std::invalid_argument("volume dimensions above 65535 are not supported by splatting");
  const double lo = volume.minValue(), hi = volume.maxValue();
  const double width = hi > lo ? hi - lo : 1.0;
  // A visibility table over the value range, so the predicate runs 4096 times, not per voxel.
  constexpr int kTable = 4096;
  std::vector<char> table(kTable);
  for (int t = 0; t < kTable; ++t) table[t] = isVisible(lo + width * t / (kTable - 1)) ? 1 : 0;
  // A table entry is visible if either neighbour sample is, so thin peaks are not lost.
  std::vector<char> visible(table);
  for (int t = 0; t + 1 < kTable; ++t) visible[t] = table[t] || table[t + 1];
  const int s = set.stride_;
  for (int64_t k = 0; k < d[2]; k += s) {
    for (int64_t j = 0; j < d[1]; j += s) {
      int64_t n = volume.index(0, j, k);
      for (int64_t i = 0; i < d[0]; i += s, n += s) {
        const double v = volume.valueAt(n);
        if (!std::isfinite(v)) continue;
        const double x = std::clamp((v - lo) / width, 0.0, 1.0);
        if (!visible[std::min(kTable - 1, int(x * (kTable - 1)))] &&
            !(alsoKeep && alsoKeep(i, j, k, v)))
          continue;
        if (set.splats_.size() >= maxSplats)
          throw SplatLimitError("more than " + std::to_string(maxSplats) +
                                " voxels are visible, the most that fit");
        set.splats_.push_back({uint32_t(i) | uint32_t(j) << 16, uint32_t(k) | quantize(x) << 16});
      }
    }
  }
  return set;
}

void SplatSet::setNormalizedValue(size_t n, double x) {
  PackedSplat& s = splats_.at(n);
  s.kValue = (s.kValue & 0xffffu) | quantize(std::clamp(x, 0.0, 1.0)) << 16;
}

}  // namespace ewa
