// TileCompositor: binning by runs of slabs, then one task a tile: the tile's slabs summed per
// pixel with each kernel's exact depth share, composited with opacity 1 - exp(-depth).
#include "core/tile_compositor.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "core/clip_share.h"
#include "core/footprint_formulas.h"
#include "core/stopwatch.h"

namespace ewa {

namespace {

constexpr int kPixels = TileCompositor::kTile * TileCompositor::kTile;

// The pixels whose centres lie in `box` (centre, half extents; shaders/tile_range.glsl's
// boxTiles before the division): false where none lies in the picture.
bool boxPixels(const glm::vec4& box, int width, int height, int& x0, int& y0, int& x1, int& y1) {
  if (!(box.z > 0.0f) || !(box.w > 0.0f)) return false;
  x0 = int(std::ceil(box.x - box.z - 0.5f));
  y0 = int(std::ceil(box.y - box.w - 0.5f));
  x1 = int(std::floor(box.x + box.z - 0.5f));
  y1 = int(std::floor(box.y + box.w - 0.5f));
  if (x0 > width - 1 || y0 > height - 1 || x1 < 0 || y1 < 0) return false;
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, width - 1);
  y1 = std::min(y1, height - 1);
  return true;
}

}  // namespace

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

void TileCompositor::compositeTile(int tx, int ty, const std::vector<SplatRecord>& records,
                                   const std::vector<Slab>& slabs, const TileCompositeSettings& s,
                                   std::vector<glm::vec4>& picture) const {
  const size_t tilesX = size_t((s.width + kTile - 1) / kTile);
  const size_t tile = size_t(ty) * tilesX + size_t(tx);
  const int px0 = tx * kTile, py0 = ty * kTile;
  const int w = std::min(kTile, s.width - px0), h = std::min(kTile, s.height - py0);
  std::array<glm::vec4, kPixels> image{};  // premultiplied, front to back
  std::array<glm::vec4, kPixels> sums{};   // (colour * optical depth, optical depth) of a slab
  std::array<RayInterval, kPixels> kept;   // the crop box and clipping planes along each ray
  const bool clipped = !s.clipPlanes.empty();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      kept[size_t(y * kTile + x)] =
          clipped ? clippedDepths(s.clipPlanes, s.proj, glm::dvec2(px0 + x + 0.5, py0 + y + 0.5))
                  : RayInterval{-kClipUnbounded, kClipUnbounded};
  const float cutoff = float(s.cutoff);
  const float termination = float(s.termination);
  const bool series = usesErfSeries(s.profile);
  const float erfReach = float(std::min(s.profile.erfReach, kClipUnbounded));
  const float halfScale = 0.5f * float(s.profile.scale);
  int open = w * h;               // pixels below the termination opacity
  uint32_t current = UINT32_MAX;  // the slab being summed
  bool any = false;               // it has sums
  const auto finishSlab = [&] {
    if (!any) return;
    open = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        glm::vec4& p = image[size_t(y * kTile + x)];
        glm::vec4& q = sums[size_t(y * kTile + x)];
        // The slab pass's pre-classified composite: opacity 1 - exp(-depth), front to back.
        if (q.a > 0.0f) {
          const float alpha = 1.0f - std::exp(-q.a);
          p += (1.0f - p.a) * glm::vec4(glm::vec3(q) / q.a * alpha, alpha);
        }
        q = glm::vec4(0.0f);
        open += p.a < termination;
      }
    any = false;
  };
  for (const std::vector<std::vector<Item>>& run : bins_) {
    for (const Item& item : run[tile]) {
      if (item.slab != current) {
        finishSlab();
        if (open == 0) break;  // every pixel opaque: the tile is done
        current = item.slab;
      }
      const SplatRecord& rec = records[item.entry & SlabPartition::kIndexMask];
      int x0, y0, x1, y1;
      if (!boxPixels(rec.box, s.width, s.height, x0, y0, x1, y1)) continue;
      x0 = std::max(x0, px0) - px0;
      y0 = std::max(y0, py0) - py0;
      x1 = std::min(x1, px0 + w - 1) - px0;
      y1 = std::min(y1, py0 + h - 1) - py0;
      const bool openNear = (item.entry & SlabPartition::kFirstSlab) != 0;
      const bool openFar = (item.entry & SlabPartition::kLastSlab) != 0;
      const Slab& slab = slabs[item.slab];
      const glm::vec3 rgb(rec.color);
      const float a = rec.conic.x, b = rec.conic.y, c = rec.conic.z;
      const float toErf = 1.0f / (std::sqrt(2.0f) * rec.depth.w);  // slabFraction's s
      // Unclipped, every pixel's share lies between the same depths.
      const RayInterval whole = slabShareBounds(slab.nearDepth, slab.farDepth, openNear, openFar,
                                                {-kClipUnbounded, kClipUnbounded});
      for (int y = y0; y <= y1; ++y) {
        const float dy = float(py0 + y) + 0.5f - rec.box.y;
        // The row's offsets within the cutoff ellipse, a dx^2 + 2 b dy dx + c dy^2 <= cutoff,
        // a pixel wider each side (the test below is exact).
        const float disc = b * b * dy * dy - a * (c * dy * dy - cutoff);
        if (!(disc >= 0.0f) || !(a > 0.0f)) continue;
        const float root = std::sqrt(disc);
        const float left = rec.box.x + (-b * dy - root) / a - 0.5f - float(px0);
        const float right = rec.box.x + (-b * dy + root) / a - 0.5f - float(px0);
        const int xa = std::max(x0, int(std::floor(left))), xb = std::min(x1, int(right) + 1);
        for (int x = xa; x <= xb; ++x) {
          const size_t p = size_t(y * kTile + x);
          if (!(image[p].a < termination)) continue;  // this pixel takes no more
          const float dx = float(px0 + x) + 0.5f - rec.box.x;
          const float r = a * dx * dx + 2.0f * b * dx * dy + c * dy * dy;
          if (!(r <= cutoff)) continue;
          const RayInterval bounds =
              clipped ? slabShareBounds(slab.nearDepth, slab.farDepth, openNear, openFar, kept[p])
                      : whole;
          if (!(bounds.far > bounds.near)) continue;
          // clippedSlabFraction in float, as the shaders take it.
          const float mu = rec.depth.x + rec.depth.y * dx + rec.depth.z * dy;
          const float share = slabShareOf(mu, toErf, float(bounds.near), float(bounds.far),
                                          erfReach, halfScale, series);
          const float depth = rec.conic.w * windowedGaussianOf(r, cutoff) * share;
          sums[p] += glm::vec4(rgb * depth, depth);
          any = true;
        }
      }
    }
    if (open == 0) break;
  }
  finishSlab();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      picture[size_t(py0 + y) * size_t(s.width) + size_t(px0 + x)] = image[size_t(y * kTile + x)];
}

TileCompositor::Timing TileCompositor::draw(const std::vector<SplatRecord>& records,
                                            const std::vector<uint32_t>& order,
                                            const std::vector<Slab>& slabs,
                                            const TileCompositeSettings& settings,
                                            std::vector<glm::vec4>& picture) {
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
  tbb::parallel_for(0, tilesX * tilesY, [&](int tile) {
    compositeTile(tile % tilesX, tile / tilesX, records, slabs, settings, picture);
  });
  t.compositeMs = millisecondsSince(start);
  return t;
}

}  // namespace ewa
