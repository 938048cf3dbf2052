// TileCompositor: binning by runs of slabs, then one task a tile: the tile's slabs summed per
// pixel with each kernel's exact depth share, composited with opacity 1 - exp(-depth).
#include "core/tile_compositor.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/stopwatch.h"

#define EWA_TILE_ISA baseline
#include "core/tile_composite_kernel.h"
#include "core/tile_post_kernel.h"

namespace ewa {

#if EWA_TILE_AVX2
namespace tile_kernel::avx2 {
// tile_compositor_avx2.cpp: gatherTileFor compiled for AVX2 and FMA.
void compositeTile(const TileWork& work, bool series, bool clipped);
}  // namespace tile_kernel::avx2
#endif

using tile_kernel::baseline::boxPixels;  // the binning's, as the composite takes it

void TileCompositor::bin(const std::vector<SplatRecord>& records,
                         const std::vector<uint32_t>& order, const std::vector<Slab>& slabs,
                         int width, int height) {
  const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
  const size_t tiles = size_t(tilesX) * size_t(tilesY);
  // Runs of whole slabs of about equal entries, a few per core.
  size_t total = 0;
  for (const Slab& s : slabs) total += s.count;
  const size_t runs = std::clamp<size_t>(total / 65536, 1, 64);
  std::vector<size_t> runFirst{0};  // slab index each run starts at
  size_t sum = 0;
  for (size_t b = 0; b < slabs.size(); ++b) {
    if (sum * runs >= total * runFirst.size() && b > runFirst.back()) runFirst.push_back(b);
    sum += slabs[b].count;
  }
  runFirst.push_back(slabs.size());
  bins_.resize(runFirst.size() - 1);
  tbb::parallel_for(size_t(0), bins_.size(), [&](size_t run) {
    std::vector<std::vector<Item>>& lists = bins_[run];
    lists.resize(tiles);
    for (std::vector<Item>& list : lists) list.clear();
    for (size_t b = runFirst[run]; b < runFirst[run + 1]; ++b) {
      const Slab& slab = slabs[b];
      for (uint32_t e = slab.first; e < slab.first + slab.count; ++e) {
        // Records in the volume's order, entries in the slabs': each asked for ahead of its turn.
        if (e + 16 < order.size())
          __builtin_prefetch(&records[order[e + 16] & SlabPartition::kIndexMask]);
        const uint32_t entry = order[e];
        int x0, y0, x1, y1;
        if (!boxPixels(records[entry & SlabPartition::kIndexMask].box, width, height, x0, y0, x1,
                       y1))
          continue;
        for (int ty = y0 / kTile; ty <= y1 / kTile; ++ty)
          for (int tx = x0 / kTile; tx <= x1 / kTile; ++tx)
            lists[size_t(ty) * size_t(tilesX) + size_t(tx)].push_back({entry, uint32_t(b)});
      }
    }
  });
}

TileCompositor::Timing TileCompositor::draw(const std::vector<SplatRecord>& records,
                                            const std::vector<uint32_t>& order,
                                            const std::vector<Slab>& slabs,
                                            const TileCompositeSettings& settings,
                                            std::vector<glm::vec4>& picture,
                                            const std::atomic<bool>* cancel) {
  Timing t;
  const int width = std::max(settings.width, 1), height = std::max(settings.height, 1);
  picture.assign(size_t(width) * size_t(height), glm::vec4(0.0f));
  auto start = std::chrono::steady_clock::now();
  bin(records, order, slabs, width, height);
  for (const auto& run : bins_)
    for (const auto& list : run) t.entries += list.size();
  t.binMs = millisecondsSince(start);
  start = std::chrono::steady_clock::now();
  const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
  const bool series = usesErfSeries(settings.profile), clipped = !settings.clipPlanes.empty();
#if EWA_TILE_AVX2
  // The machine runs the AVX2 and FMA build of the tile composite: asked once.
  static const bool machineAvx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  const bool avx2 = machineAvx2 && avx2Allowed_;
#endif
  tbb::parallel_for(0, tilesX * tilesY, [&](int tile) {
    if (cancel && cancel->load(std::memory_order_relaxed)) return;
    tile_kernel::TileWork work{&bins_,       &records, &slabs, &settings, &picture,
                               size_t(tile), 0,        0,      0,         0};
    work.px0 = (tile % tilesX) * kTile;
    work.py0 = (tile / tilesX) * kTile;
    work.w = std::min(kTile, width - work.px0);
    work.h = std::min(kTile, height - work.py0);
#if EWA_TILE_AVX2
    if (avx2) {
      tile_kernel::avx2::compositeTile(work, series, clipped);
      return;
    }
#endif
    tile_kernel::baseline::gatherTileFor(work, series, clipped);
  });
  t.compositeMs = millisecondsSince(start);
  return t;
}

}  // namespace ewa
