// SplatSet: classification of voxels into splats through a visibility table.
#include "core/splat_set.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/parallel_chunks.h"

namespace ewa {

SplatSet SplatSet::build(const Volume& volume, const std::function<bool(double)>& isVisible,
                         int stride, const VoxelPredicate& alsoKeep, size_t maxSplats,
                         unsigned threads) {
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
  // Slices of layers on the machine's cores, joined in order: the sequential loop's list.
  const size_t layers = size_t((d[2] + s - 1) / s);
  // Each chunk's splats in blocks of a fixed size: a growing vector's copies and freed pages
  // (whose unmapping interrupts every core) kept many threads from being much faster than a few.
  constexpr size_t kBlock = size_t(1) << 18;
  const size_t minLayers = minItemsPerChunk(size_t((d[0] + s - 1) / s * ((d[1] + s - 1) / s)));
  std::atomic<size_t> kept{0};  // all chunks' splats so far, checked a row at a time
  auto tooMany = [maxSplats] {
    return SplatLimitError("more than " + std::to_string(maxSplats) +
                           " voxels are visible, the most that fit");
  };
  using Blocks = std::vector<std::vector<PackedSplat>>;
  std::vector<Blocks> parts =
      parallelChunkResults<Blocks>(layers, minLayers, threads, [&](size_t first, size_t last) {
        Blocks blocks;
        size_t count = 0;  // this chunk's splats
        for (int64_t k = int64_t(first) * s; k < int64_t(last) * s && k < d[2]; k += s) {
          for (int64_t j = 0; j < d[1]; j += s) {
            const size_t before = count;
            int64_t n = volume.index(0, j, k);
            for (int64_t i = 0; i < d[0]; i += s, n += s) {
              const double v = volume.valueAt(n);
              if (!std::isfinite(v)) continue;
              const double x = std::clamp((v - lo) / width, 0.0, 1.0);
              if (!visible[std::min(kTable - 1, int(x * (kTable - 1)))] &&
                  !(alsoKeep && alsoKeep(i, j, k, v)))
                continue;
              if (count >= maxSplats) throw tooMany();
              if (blocks.empty() || blocks.back().size() == kBlock) {
                blocks.emplace_back();
                blocks.back().reserve(kBlock);
              }
              blocks.back().push_back(
                  {uint32_t(i) | uint32_t(j) << 16, uint32_t(k) | quantize(x) << 16});
              ++count;
            }
            if (kept.fetch_add(count - before) + (count - before) > maxSplats) throw tooMany();
          }
        }
        return blocks;
      });
  // Each chunk's blocks copied to their place in the list on its own thread, and freed.
  std::vector<size_t> offsets(parts.size() + 1, 0);
  for (size_t c = 0; c < parts.size(); ++c) {
    offsets[c + 1] = offsets[c];
    for (const auto& block : parts[c]) offsets[c + 1] += block.size();
  }
  set.splats_.resize(offsets.back());
  parallelChunks(parts.size(), 1, threads, [&](size_t first, size_t last, size_t) {
    for (size_t c = first; c < last; ++c) {
      PackedSplat* out = set.splats_.data() + offsets[c];
      for (std::vector<PackedSplat>& block : parts[c]) {
        out = std::copy(block.begin(), block.end(), out);
        std::vector<PackedSplat>().swap(block);
      }
    }
  });
  return set;
}

void SplatSet::setNormalizedValue(size_t n, double x) {
  PackedSplat& s = splats_.at(n);
  s.kValue = (s.kValue & 0xffffu) | quantize(std::clamp(x, 0.0, 1.0)) << 16;
}

}  // namespace ewa
