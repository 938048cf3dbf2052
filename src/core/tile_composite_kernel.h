// The CPU splatter's per-tile composite (core/tile_compositor.h), compiled once per instruction
// set: tile_compositor.cpp for the build's baseline, tile_compositor_avx2.cpp for AVX2 and FMA,
// each in its own namespace (EWA_TILE_ISA, defined before this header), so no inline function
// of one is taken for the other. The shared formulas they call (ewa namespace) are always
// inlined: an out-of-line copy from the AVX2 file could be the one the linker keeps for every
// caller (the test tile_kernel_isa_symbols checks). Include it from those two files only.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "core/clip_share.h"
#include "core/covered_length.h"
#include "core/footprint_formulas.h"
#include "core/tile_compositor.h"

#ifndef EWA_TILE_ISA
#error "define EWA_TILE_ISA (the instruction set's namespace) before including this header"
#endif

namespace ewa::tile_kernel {

// What a tile's pixel loops share in a pass.
struct TileWork {
  const std::vector<TileCompositor::Run>* bins;
  const SplatRecord* records;  // the pass's, at the items' places
  const std::vector<Slab>* slabs;
  const TileCompositeSettings* settings;
  std::vector<glm::vec4>* picture;
  TileCompositor::TileState* state;
  size_t tile;
  int px0, py0, w, h;
};

namespace EWA_TILE_ISA {

constexpr int kPixels = TileCompositor::kPixels;

// The pixels whose centres lie in `box` (centre, half extents; shaders/tile_range.glsl's
// boxTiles before the division): false where none lies in the picture.
inline bool boxPixels(const glm::vec4& box, int width, int height, int& x0, int& y0, int& x1,
                      int& y1) {
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

// Calls `take(item)` for the tile's items in slab order, front to back or (`reverse`) back to
// front, until it returns false.
template <typename Take>
__attribute__((always_inline)) inline void forEachTileItem(const TileWork& work, bool reverse,
                                                           Take&& take) {
  const auto& runs = *work.bins;
  const SplatRecord* records = work.records;
  // The records lie in the volume's order, the tile's items jump about them: each is asked
  // for from memory a few items ahead, so it is in the cache when its turn comes.
  constexpr size_t kAhead = 8;
  const auto prefetch = [&](const TileCompositor::Item& item) __attribute__((always_inline)) {
    __builtin_prefetch(records + (item.entry & SlabPartition::kIndexMask));
  };
  if (!reverse) {
    for (const auto& run : runs) {
      const TileCompositor::Item* list = run.items.data() + run.start[work.tile];
      const size_t n = run.count(work.tile);
      for (size_t i = 0; i < std::min(n, kAhead); ++i) prefetch(list[i]);
      for (size_t i = 0; i < n; ++i) {
        if (i + kAhead < n) prefetch(list[i + kAhead]);
        if (!take(list[i])) return;
      }
    }
    return;
  }
  for (size_t r = runs.size(); r-- > 0;) {
    const TileCompositor::Item* list = runs[r].items.data() + runs[r].start[work.tile];
    const size_t n = runs[r].count(work.tile);
    for (size_t i = 0; i < std::min(n, kAhead); ++i) prefetch(list[n - 1 - i]);
    for (size_t i = n; i-- > 0;) {
      if (i >= kAhead) prefetch(list[i - kAhead]);
      if (!take(list[i])) return;
    }
  }
}

// Calls `run(first, n)` for the row's columns [xa, xb]: one run of 8 pixels (one AVX2 vector)
// where they fit in one, else the tile's whole row of 16.
template <typename Run>
__attribute__((always_inline)) inline void forRowRun(int xa, int xb, Run&& run) {
  if (xb - xa < 8)
    run(std::min(xa, TileCompositor::kTile - 8), std::integral_constant<int, 8>());
  else
    run(0, std::integral_constant<int, TileCompositor::kTile>());
}

// The tile's pixels still taking slabs, a bit a pixel and a word a row: a kernel's row whose
// columns hold none is skipped (its pixels would each add a masked 0).
struct LiveRows {
  uint32_t bits[TileCompositor::kTile];
  void update(const float* live) {
    for (int y = 0; y < TileCompositor::kTile; ++y) {
      uint32_t row = 0;
      for (int x = 0; x < TileCompositor::kTile; ++x)
        row |= uint32_t(live[y * TileCompositor::kTile + x] > 0.0f) << x;
      bits[y] = row;
    }
  }
  // Whether any pixel takes more slabs (none: the tile is done).
  bool any() const {
    uint32_t all = 0;
    for (uint32_t row : bits) all |= row;
    return all != 0;
  }
  // The bits of columns x0 to x1.
  static uint32_t columns(int x0, int x1) { return ((2u << x1) - 1u) & ~((1u << x0) - 1u); }
};

// One tile's pixels as planes (structure of arrays, rows kTile apart): a row of 16 pixels is
// two AVX2 vectors.
struct TilePlanes {
  alignas(32) float r[kPixels];
  alignas(32) float g[kPixels];
  alignas(32) float b[kPixels];
  alignas(32) float a[kPixels];
};

// The pixels of the tile (tile-local, inclusive) whose centres lie in `rec`'s box: false where
// none does.
inline bool tileBox(const TileWork& work, const SplatRecord& rec, int& x0, int& y0, int& x1,
                    int& y1) {
  const TileCompositeSettings& s = *work.settings;
  if (!boxPixels(rec.box, s.width, s.height, x0, y0, x1, y1)) return false;
  x0 = std::max(x0, work.px0) - work.px0;
  y0 = std::max(y0, work.py0) - work.py0;
  x1 = std::min(x1, work.px0 + work.w - 1) - work.px0;
  y1 = std::min(y1, work.py0 + work.h - 1) - work.py0;
  return true;
}

// Writes the tile's pixels to the picture: `pixel(p)` gives the one at plane index p.
template <typename Pixel>
inline void storeTile(const TileWork& work, Pixel&& pixel) {
  const size_t width = size_t(work.settings->width);
  for (int y = 0; y < work.h; ++y)
    for (int x = 0; x < work.w; ++x)
      (*work.picture)[size_t(work.py0 + y) * width + size_t(work.px0 + x)] =
          pixel(y * TileCompositor::kTile + x);
}

// The tile's pixels from the picture (what the passes before left), as planes.
inline void loadTile(const TileWork& work, TilePlanes& image) {
  const size_t width = size_t(work.settings->width);
  for (int p = 0; p < kPixels; ++p) image.r[p] = image.g[p] = image.b[p] = image.a[p] = 0.0f;
  for (int y = 0; y < work.h; ++y)
    for (int x = 0; x < work.w; ++x) {
      const glm::vec4 v = (*work.picture)[size_t(work.py0 + y) * width + size_t(work.px0 + x)];
      const int p = y * TileCompositor::kTile + x;
      image.r[p] = v.r;
      image.g[p] = v.g;
      image.b[p] = v.b;
      image.a[p] = v.a;
    }
}

// The tile's pixel constants, set in its first pass: which pixels lie in the picture, the
// clip region along each ray (nothing kept: both bounds at one depth, every share 0) and,
// post-classified (`box`), the data's box along it and its stretch.
inline void beginTile(const TileWork& work, bool clipped, bool box) {
  const TileCompositeSettings& s = *work.settings;
  TileCompositor::TileState& st = *work.state;
  const float unbounded = float(kClipUnbounded);
  for (int p = 0; p < kPixels; ++p) {
    const int x = p % TileCompositor::kTile, y = p / TileCompositor::kTile;
    const bool inside = x < work.w && y < work.h;
    st.live[p] = inside ? 1.0f : 0.0f;
    st.last[p] = 0.0f;
    st.hasLast[p] = false;
    st.keptNear[p] = -unbounded;
    st.keptFar[p] = unbounded;
    st.boxNear[p] = st.boxFar[p] = 0.0f;
    st.stretch[p] = 1.0f;
    if (!inside) continue;
    const glm::dvec2 centre(work.px0 + x + 0.5, work.py0 + y + 0.5);
    if (clipped) {
      const RayInterval kept = clippedDepths(s.clipPlanes, s.proj, centre);
      st.keptNear[p] = float(std::clamp(kept.near, -kClipUnbounded, kClipUnbounded));
      st.keptFar[p] =
          std::max(st.keptNear[p], float(std::clamp(kept.far, -kClipUnbounded, kClipUnbounded)));
    }
    if (box) {
      const IndexRay ray = indexRay(s.cameraToIndex, s.proj, centre);
      const RayInterval depths = boxDepths(ray.origin, ray.direction, s.dataBox);
      st.boxNear[p] = float(std::clamp(depths.near, -kClipUnbounded, kClipUnbounded));
      st.boxFar[p] = float(std::clamp(depths.far, -kClipUnbounded, kClipUnbounded));
      st.stretch[p] = float(rayStretch(s.proj, centre));
    }
  }
  st.begun = true;
}

// The tile's slabs summed and composited front to back. Each row of a splat's box is walked over
// an aligned run of 8 pixels (a footprint within one half of the tile's row) or the whole row of
// 16, the pixels outside its box, its ellipse or the picture or already opaque adding 0: no
// branches in the pixel loop, which the compiler vectorizes.
template <bool Series, bool Clipped>
__attribute__((always_inline)) inline void compositeTileOf(const TileWork& work) {
  constexpr int kTile = TileCompositor::kTile;
  const TileCompositeSettings& s = *work.settings;
  const int px0 = work.px0, py0 = work.py0;
  const float cutoff = float(s.cutoff);
  const bool backToFront = s.backToFront;
  // Back to front nothing terminates: every slab is drawn.
  const float termination = backToFront ? 2.0f : float(s.termination);
  const float erfReach = float(std::min(s.profile.erfReach, kClipUnbounded));
  const float halfScale = 0.5f * float(s.profile.scale);
  TileCompositor::TileState& state = *work.state;
  if (!state.begun) beginTile(work, Clipped, false);
  float* live = state.live;                // 1 where the pixel is in the picture and takes more
  const float* keptNear = state.keptNear;  // the clip region along each ray
  const float* keptFar = state.keptFar;
  TilePlanes image, sums;
  loadTile(work, image);
  for (int p = 0; p < kPixels; ++p) sums.r[p] = sums.g[p] = sums.b[p] = sums.a[p] = 0.0f;
  alignas(32) float centreX[kTile];  // pixel centres, x
  for (int x = 0; x < kTile; ++x) centreX[x] = float(px0 + x) + 0.5f;
  LiveRows liveRows;
  liveRows.update(live);
  uint32_t current = UINT32_MAX;  // the slab being summed
  bool any = false;               // it has sums
  const auto finishSlab = [&]() __attribute__((always_inline)) {
    if (!any) return;
    for (int p = 0; p < kPixels; ++p) {
      // The slab pass's pre-classified composite: opacity 1 - exp(-depth), front to back.
      const float depth = sums.a[p];
      const float alpha = depth > 0.0f ? 1.0f - expOf(-depth) : 0.0f;
      // Front to back the slab goes under what is there, back to front over it.
      const float under = backToFront ? 1.0f : 1.0f - image.a[p];
      const float over = backToFront ? 1.0f - alpha : 1.0f;
      const float weight = depth > 0.0f ? under * alpha / depth : 0.0f;
      image.r[p] = over * image.r[p] + weight * sums.r[p];
      image.g[p] = over * image.g[p] + weight * sums.g[p];
      image.b[p] = over * image.b[p] + weight * sums.b[p];
      image.a[p] = over * image.a[p] + under * alpha;
      sums.r[p] = sums.g[p] = sums.b[p] = sums.a[p] = 0.0f;
      live[p] = live[p] > 0.0f && image.a[p] < termination ? 1.0f : 0.0f;
    }
    liveRows.update(live);
    any = false;
  };
  forEachTileItem(work, backToFront, [&](const TileCompositor::Item& item) {
    if (item.slab != current) {
      finishSlab();
      if (!liveRows.any()) return false;  // every pixel opaque: the tile is done
      current = item.slab;
    }
    const SplatRecord& rec = work.records[item.entry & SlabPartition::kIndexMask];
    int x0, y0, x1, y1;
    if (!tileBox(work, rec, x0, y0, x1, y1)) return true;
    const bool openNear = (item.entry & SlabPartition::kFirstSlab) != 0;
    const bool openFar = (item.entry & SlabPartition::kLastSlab) != 0;
    const Slab& slab = (*work.slabs)[item.slab];
    const float zNear = float(std::clamp(slab.nearDepth, -kClipUnbounded, kClipUnbounded));
    const float zFar = float(std::clamp(slab.farDepth, -kClipUnbounded, kClipUnbounded));
    const float cr = rec.color.r, cg = rec.color.g, cb = rec.color.b;
    const float qa = rec.conic.x, qb = rec.conic.y, qc = rec.conic.z, amplitude = rec.conic.w;
    const float cx = rec.box.x, mu0 = rec.depth.x;
    const float slopeX = s.flatDepths ? 0.0f : rec.depth.y;
    const float slopeY = s.flatDepths ? 0.0f : rec.depth.z;
    const float toErf = 1.0f / (std::sqrt(2.0f) * rec.depth.w);  // slabFraction's s
    // Unclipped, every pixel's share lies between the same depths.
    float wholeLo, wholeHi;
    slabShareBoundsOf(zNear, zFar, openNear, openFar, -float(kClipUnbounded), float(kClipUnbounded),
                      wholeLo, wholeHi);
    any = true;
    const uint32_t columns = LiveRows::columns(x0, x1);
    for (int y = y0; y <= y1; ++y) {
      if (!(liveRows.bits[y] & columns)) continue;
      const float dy = float(py0 + y) + 0.5f - rec.box.y;
      const float rowR = qc * dy * dy, rowMu = mu0 + slopeY * dy;
      // Pixels [first, first + n) of the row; every term computed, each pixel's share masked.
      const auto addRun = [&](int first, auto n) __attribute__((always_inline)) {
        const int at = y * kTile + first;
        float* __restrict sr = sums.r + at;
        float* __restrict sg = sums.g + at;
        float* __restrict sb = sums.b + at;
        float* __restrict sa = sums.a + at;
        const float* lv = live + at;
        const float* kn = keptNear + at;
        const float* kf = keptFar + at;
        const float* xc = centreX + first;
        for (int i = 0; i < decltype(n)::value; ++i) {
          const int x = first + i;
          const float dx = xc[i] - cx;
          const float r = qa * dx * dx + 2.0f * qb * dx * dy + rowR;
          float lo = wholeLo, hi = wholeHi;
          if (Clipped) slabShareBoundsOf(zNear, zFar, openNear, openFar, kn[i], kf[i], lo, hi);
          // clippedSlabFraction in float, as the shaders take it.
          const float mu = rowMu + slopeX * dx;
          const float share = slabShareOf(mu, toErf, lo, hi, erfReach, halfScale, Series);
          const bool take = (x >= x0) & (x <= x1) & (lv[i] > 0.0f) & (hi > lo);
          const float weight = amplitude * windowedGaussianOf(std::min(r, cutoff), cutoff) * share;
          const float mask = take ? 1.0f : 0.0f;  // a product: no branch
          const float depth = weight * mask;
          sr[i] += cr * depth;
          sg[i] += cg * depth;
          sb[i] += cb * depth;
          sa[i] += depth;
        }
      };
      // A footprint within one half of the tile's row takes one vector of 8, else the row.
      forRowRun(x0, x1, addRun);
    }
    return true;
  });
  finishSlab();
  state.done = !liveRows.any();
  storeTile(work, [&](int p) { return glm::vec4(image.r[p], image.g[p], image.b[p], image.a[p]); });
}

}  // namespace EWA_TILE_ISA

}  // namespace ewa::tile_kernel
