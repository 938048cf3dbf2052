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

namespace {

// Cuts slabs [first, end) into at most `parts` runs of whole slabs of about equal entries: the
// slab index each run starts at, then `end`.
std::vector<size_t> splitSlabs(const std::vector<Slab>& slabs, size_t first, size_t end,
                               size_t parts) {
  size_t total = 0;
  for (size_t b = first; b < end; ++b) total += slabs[b].count;
  std::vector<size_t> starts{first};
  size_t sum = 0;
  for (size_t b = first; b < end; ++b) {
    if (sum * parts >= total * starts.size() && b > starts.back()) starts.push_back(b);
    sum += slabs[b].count;
  }
  starts.push_back(end);
  return starts;
}

// `v` resized to `n`, its storage grown to n exactly (a vector grows by doubling): the bytes
// held are the largest pass's.
template <typename T>
void resizeExactly(std::vector<T>& v, size_t n) {
  if (n > v.capacity()) {
    std::vector<T>().swap(v);
    v.reserve(n);
  }
  v.resize(n);
}

// Whether slab `b`'s entry `entry` is its splat's first in the pass that begins at slab `first`.
bool firstInPass(uint32_t entry, size_t b, size_t first) {
  return (entry & SlabPartition::kFirstSlab) != 0 || b == first;
}

}  // namespace

void TileCompositor::makeRecords(const SplatRecordMaker& maker, const std::vector<uint32_t>& order,
                                 const std::vector<Slab>& slabs, size_t first, size_t end,
                                 const std::vector<size_t>& placeOf) {
  resizeExactly(records_, placeOf[end - first]);
  if (places_.size() < maker.size()) resizeExactly(places_, maker.size());
  // A splat's record is made at its first slab in the pass and found by its place at the others
  // (the binning reads places_ after every record is made).
  tbb::parallel_for(first, end, [&](size_t b) {
    const Slab& slab = slabs[b];
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, slab.count, 4096),
                      [&](const tbb::blocked_range<uint32_t>& r) {
                        // A slab's splats lie far apart in the volume's order: each asked for
                        // ahead.
                        const uint32_t* entries = order.data() + slab.first;
                        for (uint32_t i = r.begin(); i != r.end(); ++i) {
                          if (i + 16 < r.end())
                            maker.prefetch(entries[i + 16] & SlabPartition::kIndexMask);
                          const uint32_t entry = entries[i];
                          if (!firstInPass(entry, b, first)) continue;
                          const uint32_t splat = entry & SlabPartition::kIndexMask;
                          const size_t place = placeOf[b - first] + i;
                          records_[place] = maker(splat);
                          places_[splat] = uint32_t(place);
                        }
                      });
  });
}

void TileCompositor::bin(const std::vector<uint32_t>& order, const std::vector<Slab>& slabs,
                         size_t first, size_t end, const std::vector<size_t>& placeOf, int width,
                         int height) {
  const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
  const size_t tiles = size_t(tilesX) * size_t(tilesY);
  // Runs of whole slabs of about equal entries, a few per core.
  size_t total = 0;
  for (size_t b = first; b < end; ++b) total += slabs[b].count;
  const std::vector<size_t> runFirst =
      splitSlabs(slabs, first, end, std::clamp<size_t>(total / 65536, 1, 64));
  bins_.resize(runFirst.size() - 1);
  tbb::parallel_for(size_t(0), bins_.size(), [&](size_t run) {
    Run& bins = bins_[run];
    // Each entry's record and the tiles its box reaches, for `add(tile, item)`.
    const auto forEachItem = [&](auto&& add) {
      for (size_t b = runFirst[run]; b < runFirst[run + 1]; ++b) {
        const Slab& slab = slabs[b];
        const uint32_t* entries = order.data() + slab.first;
        for (uint32_t i = 0; i < slab.count; ++i) {
          // A splat's later slabs find its record by its place: asked for ahead of its turn.
          if (i + 16 < slab.count)
            __builtin_prefetch(&places_[entries[i + 16] & SlabPartition::kIndexMask]);
          const uint32_t entry = entries[i];
          const uint32_t place = firstInPass(entry, b, first)
                                     ? uint32_t(placeOf[b - first] + i)
                                     : places_[entry & SlabPartition::kIndexMask];
          int x0, y0, x1, y1;
          if (!boxPixels(records_[place].box, width, height, x0, y0, x1, y1)) continue;
          const Item item{place | (entry & ~SlabPartition::kIndexMask), uint32_t(b)};
          for (int ty = y0 / kTile; ty <= y1 / kTile; ++ty)
            for (int tx = x0 / kTile; tx <= x1 / kTile; ++tx) {
              const size_t tile = size_t(ty) * size_t(tilesX) + size_t(tx);
              if (!tiles_[tile].done) add(tile, item);
            }
        }
      }
    };
    // Counted, then placed: each tile's items in one array of the run, no slack.
    bins.start.assign(tiles + 1, 0);
    forEachItem([&](size_t tile, const Item&) { ++bins.start[tile + 1]; });
    for (size_t tile = 0; tile < tiles; ++tile) bins.start[tile + 1] += bins.start[tile];
    resizeExactly(bins.items, bins.start[tiles]);
    std::vector<uint32_t> cursor(bins.start.begin(), bins.start.end() - 1);
    forEachItem([&](size_t tile, const Item& item) { bins.items[cursor[tile]++] = item; });
  });
}

TileCompositor::Timing TileCompositor::draw(const SplatRecordMaker& maker,
                                            const std::vector<uint32_t>& order,
                                            const std::vector<Slab>& slabs,
                                            const TileCompositeSettings& settings,
                                            std::vector<glm::vec4>& picture,
                                            const std::atomic<bool>* cancel) {
  Timing t;
  const int width = std::max(settings.width, 1), height = std::max(settings.height, 1);
  picture.assign(size_t(width) * size_t(height), glm::vec4(0.0f));
  const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
  tiles_.resize(size_t(tilesX) * size_t(tilesY));
  for (TileState& tile : tiles_) {
    tile.begun = tile.done = false;
    tile.previous = UINT32_MAX;
  }
  const bool series = usesErfSeries(settings.profile), clipped = !settings.clipPlanes.empty();
#if EWA_TILE_AVX2
  // The machine runs the AVX2 and FMA build of the tile composite: asked once.
  static const bool machineAvx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  const bool avx2 = machineAvx2 && avx2Allowed_;
#endif
  size_t total = 0;
  for (const Slab& s : slabs) total += s.count;
  const std::vector<size_t> passFirst = splitSlabs(
      slabs, 0, slabs.size(), std::max(passes_, (total + kPassEntries - 1) / kPassEntries));
  const size_t passes = passFirst.size() - 1;
  for (size_t k = 0; k < passes; ++k) {
    if (cancel && cancel->load()) break;
    // Composited back to front the passes go from the back, each read backwards (X-ray and
    // MIP read their items front to back in either order).
    const bool reverse = settings.backToFront && (settings.gather == TileGather::Pre ||
                                                  settings.gather == TileGather::Post);
    const size_t pass = reverse ? passes - 1 - k : k;
    const size_t first = passFirst[pass], end = passFirst[pass + 1];
    std::vector<size_t> placeOf{0};  // each slab's first record in the pass, then their count
    for (size_t b = first; b < end; ++b) placeOf.push_back(placeOf.back() + slabs[b].count);
    auto start = std::chrono::steady_clock::now();
    makeRecords(maker, order, slabs, first, end, placeOf);
    t.recordsMs += millisecondsSince(start);
    start = std::chrono::steady_clock::now();
    bin(order, slabs, first, end, placeOf, width, height);
    for (const Run& run : bins_) t.entries += run.items.size();
    t.binMs += millisecondsSince(start);
    start = std::chrono::steady_clock::now();
    tbb::parallel_for(0, tilesX * tilesY, [&](int tile) {
      if (cancel && cancel->load(std::memory_order_relaxed)) return;
      bool listed = false;
      for (const Run& run : bins_) listed = listed || run.count(size_t(tile)) > 0;
      if (!listed) return;
      tile_kernel::TileWork work{&bins_,
                                 records_.data(),
                                 &slabs,
                                 &settings,
                                 &picture,
                                 &tiles_[size_t(tile)],
                                 size_t(tile),
                                 0,
                                 0,
                                 0,
                                 0};
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
    t.compositeMs += millisecondsSince(start);
  }
  size_t binBytes = 0;
  for (const Run& run : bins_)
    binBytes += run.items.capacity() * sizeof(Item) + run.start.capacity() * sizeof(uint32_t);
  t.bytes =
      records_.capacity() * sizeof(SplatRecord) + places_.capacity() * sizeof(uint32_t) + binBytes;
  return t;
}

}  // namespace ewa
