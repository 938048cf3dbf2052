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

// The slabs cut into passes of `steps` steps of the partition's slab grid each, counted from
// depth 0: the grid's anchor fixes it, so frames on one grid (a brick and the whole it is cut
// from, the ranks of a cluster) split alike. The slab index each pass starts at, then the count.
std::vector<size_t> passStarts(const std::vector<Slab>& slabs, size_t steps) {
  if (steps == SIZE_MAX) return {0, slabs.size()};
  std::vector<size_t> starts{0};
  int64_t key = 0;
  for (size_t b = 0; b < slabs.size(); ++b) {
    const double thickness = slabs[b].farDepth - slabs[b].nearDepth;
    // The step of the slab's middle, half a slab from the grid's planes.
    const double step = std::floor(0.5 * (slabs[b].nearDepth + slabs[b].farDepth) / thickness);
    const int64_t k = int64_t(std::floor(step / double(steps)));
    if (b > 0 && k != key) starts.push_back(b);
    key = k;
  }
  starts.push_back(slabs.size());
  return starts;
}

// The most slab-grid steps a pass may span for each pass to hold about `budget` bytes at most:
// a frame's `entries` in one pass take `onePass`, of which `fixed` (each splat's place) every
// pass holds and the rest in proportion to the pass's entries. The slabs' entries are uneven
// in depth, so the pass of most entries decides.
size_t passSteps(const std::vector<Slab>& slabs, size_t entries, double onePass, double fixed,
                 double budget) {
  if (onePass <= budget) return SIZE_MAX;
  size_t steps = std::max<size_t>(1, size_t(double(slabs.size()) * budget / onePass));
  for (; steps > 1; --steps) {
    const std::vector<size_t> starts = passStarts(slabs, steps);
    size_t most = 0;
    for (size_t pass = 0; pass + 1 < starts.size(); ++pass) {
      size_t count = 0;
      for (size_t b = starts[pass]; b < starts[pass + 1]; ++b) count += slabs[b].count;
      most = std::max(most, count);
    }
    if (fixed + (onePass - fixed) * double(most) / double(std::max<size_t>(entries, 1)) <= budget)
      break;
  }
  return steps;
}

// `v` resized to `n`, its storage grown to n exactly (a vector grows by doubling): the bytes
// held are the largest pass's.
template <typename Vector>
void resizeExactly(Vector& v, size_t n) {
  if (n > v.capacity()) {
    Vector().swap(v);
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
                                 int width, int height, int border) {
  if (places_.size() < maker.size()) resizeExactly(places_, maker.size());
  // Each splat's first entry in the pass takes the next place, slab by slab: the slabs' counts
  // of such entries, then each slab's places in parallel.
  std::vector<size_t> slabPlace(end - first + 1, 0);
  tbb::parallel_for(first, end, [&](size_t b) {
    const Slab& slab = slabs[b];
    size_t count = 0;
    for (uint32_t i = 0; i < slab.count; ++i)
      count += firstInPass(order[slab.first + i], b, first) ? 1 : 0;
    slabPlace[b - first + 1] = count;
  });
  for (size_t b = 1; b < slabPlace.size(); ++b) slabPlace[b] += slabPlace[b - 1];
  const size_t count = slabPlace.back();
  resizeExactly(splatsOf_, count);
  resizeExactly(records_, count);
  resizeExactly(rects_, count);
  tbb::parallel_for(first, end, [&](size_t b) {
    const Slab& slab = slabs[b];
    size_t place = slabPlace[b - first];
    for (uint32_t i = 0; i < slab.count; ++i) {
      const uint32_t entry = order[slab.first + i];
      if (!firstInPass(entry, b, first)) continue;
      const uint32_t splat = entry & SlabPartition::kIndexMask;
      places_[splat] = uint32_t(place);
      splatsOf_[place++] = splat;
    }
  });
  // The records in place order, with the tiles each reaches; a slab's splats lie far apart in
  // the volume's order, each is asked for from memory ahead of its turn.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 4096),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t place = r.begin(); place != r.end(); ++place) {
                        if (place + 16 < r.end()) maker.prefetch(splatsOf_[place + 16]);
                        const SplatRecord record = maker(splatsOf_[place]);
                        records_[place] = record;
                        int x0, y0, x1, y1;
                        TileRect& rect = rects_[place];
                        if (!boxPixels(record.box, width, height, x0, y0, x1, y1)) {
                          rect = {1, 0, 0, 0};  // none
                          continue;
                        }
                        x0 = std::max(x0 - border, 0);
                        y0 = std::max(y0 - border, 0);
                        x1 = std::min(x1 + border, width - 1);
                        y1 = std::min(y1 + border, height - 1);
                        rect = {uint16_t(x0 / kTile), uint16_t(y0 / kTile), uint16_t(x1 / kTile),
                                uint16_t(y1 / kTile)};
                      }
                    });
}

void TileCompositor::bin(const std::vector<uint32_t>& order, const std::vector<Slab>& slabs,
                         size_t first, size_t end, int width, int height) {
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
          // Each entry finds its splat's record by its place: asked for ahead of its turn.
          if (i + 16 < slab.count)
            __builtin_prefetch(&places_[entries[i + 16] & SlabPartition::kIndexMask]);
          const uint32_t entry = entries[i];
          const uint32_t place = places_[entry & SlabPartition::kIndexMask];
          const TileRect rect = rects_[place];
          const Item item{place | (entry & ~SlabPartition::kIndexMask), uint32_t(b)};
          for (int ty = rect.y0; ty <= rect.y1; ++ty)
            for (int tx = rect.x0; tx <= rect.x1; ++tx) {
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
  size_t entries = 0;
  for (const Slab& s : slabs) entries += s.count;
  // A splat's record, tiles, place and splat index; 1.75 items an entry (about the shared
  // volumes' default views at 512²).
  constexpr double kSplatBytes = sizeof(SplatRecord) + sizeof(TileRect) + 2 * sizeof(uint32_t);
  constexpr double kEntryBytes = 1.75 * sizeof(Item);
  const double onePass = kSplatBytes * double(maker.size()) + kEntryBytes * double(entries);
  const double budget = double(passBytes_ > 0 ? passBytes_ : passBudget(maker.size()));
  const size_t steps = passSlabs_ > 0 ? passSlabs_
                                      : passSteps(slabs, entries, onePass,
                                                  sizeof(uint32_t) * double(maker.size()), budget);
  const std::vector<size_t> passFirst = passStarts(slabs, steps);
  const size_t passes = passFirst.size() - 1;
  // Composited back to front the passes go from the back, each read backwards (X-ray and MIP
  // read their items front to back in either order).
  const bool reverse = settings.backToFront &&
                       (settings.gather == TileGather::Pre || settings.gather == TileGather::Post);
  // Field normals read a pixel's neighbours: a tile takes the kernels reaching a pixel about it.
  const int border =
      settings.gather == TileGather::Post && settings.normals == TileNormals::Field ? 1 : 0;
  for (size_t k = 0; k < passes; ++k) {
    if (cancel && cancel->load()) break;
    const size_t pass = reverse ? passes - 1 - k : k;
    const size_t first = passFirst[pass], end = passFirst[pass + 1];
    auto start = std::chrono::steady_clock::now();
    makeRecords(maker, order, slabs, first, end, width, height, border);
    t.recordsMs += millisecondsSince(start);
    start = std::chrono::steady_clock::now();
    bin(order, slabs, first, end, width, height);
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
  t.bytes = records_.capacity() * sizeof(SplatRecord) + rects_.capacity() * sizeof(TileRect) +
            (places_.capacity() + splatsOf_.capacity()) * sizeof(uint32_t) + binBytes;
  return t;
}

}  // namespace ewa
