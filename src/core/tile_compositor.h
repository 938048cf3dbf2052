// TileCompositor: the CPU splatter's composite, in the compute tiles' shape
// (shaders/tile_ewa.comp.glsl): screen tiles, each slab entry binned to the tiles its box
// reaches in slab order, each tile's slabs added up, composited front to back and left once
// every pixel is opaque, one tile a task over all cores. A frame too large for kPassBytes goes
// in passes of a few slabs each, so the records and bins held at once are a pass's.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "core/camera.h"
#include "core/clip_region.h"
#include "core/default_init_allocator.h"
#include "core/ewa_footprint.h"
#include "core/gradient_volume.h"
#include "core/shading.h"
#include "core/slab_partition.h"
#include "core/splat_records.h"
#include "core/volume.h"

namespace ewa {

// What a tile's pixels gather (the splat shaders' variants): pre-classified optical depth and
// colour composited slab by slab; post-classified kernel-weighted values classified per pixel
// (TileCompositeSettings::samples); X-ray's summed optical depth; MIP's largest weighted value.
enum class TileGather { Pre, Post, XRay, Mip };

// Post-classified with shading: the normal each pixel's slab is lit by (the slab pass's
// variants, shaders/slab_classify.glsl): the splats' voxel normals summed over the slab with
// their weights (Voxel), the data's gradient read along the pixel's ray at each segment's
// middle (Ray, core/gradient_volume.h), or the gradient of the reconstructed field from the
// neighbouring pixels' values (Field, core/field_gradient.h; pre-integrated only); None:
// unshaded.
enum class TileNormals { None, Voxel, Ray, Field };

// Post-classification's tables (the textures the slab pass reads), borrowed for the frame.
struct TileClassifyTables {
  // Pre-integrated: slabPairTexels (pairSize squared) and the extinction prefix.
  const glm::vec4* pairTexels = nullptr;
  int pairSize = 0;
  const float* prefix = nullptr;
  int prefixSize = 0;
  // Without pre-integration: the baked 1D transfer function (rgb, extinction per world unit).
  const glm::vec4* transfer = nullptr;
  int transferSize = 0;
};

// The frame's scalars: picture size, footprint cutoff, the kernels' depth profile (the slab
// split), termination opacity, and the clip region (camera space) with the projection its
// pixel rays come from.
struct TileCompositeSettings {
  int width = 1;
  int height = 1;
  double cutoff = 5.0;
  DepthProfile profile;
  double termination = 0.99;  // a pixel stops taking slabs at this opacity (>= 1: never)
  std::vector<HalfSpace> clipPlanes;
  Projection proj;
  TileGather gather = TileGather::Pre;
  bool backToFront = false;  // the slabs composited from the back, with no termination
  // Post: depth samples a slab, 4 (quarters) or 2 (halves), pre-integrated between them and
  // the neighbouring slab's; 1: each slab's mean value classified alone.
  int samples = 4;
  TileClassifyTables tables;
  // Post: the covered lengths end at the data's box (core/covered_length.h).
  glm::dmat4 cameraToIndex{1.0};
  DataBox dataBox;
  // Post with shading: the head light and the normals it takes; Ray reads `gradients`, which
  // stay alive and unchanged while the frame is drawn.
  TileNormals normals = TileNormals::None;
  Lighting lighting;
  const PackedGradients* gradients = nullptr;
  // Test hook: every pixel takes a kernel's slab shares at the kernel centre's depth (its
  // depth slopes dropped), a wrong slab split that the tests must catch.
  bool flatDepths = false;
};

class TileCompositor {
 public:
  // Pixels a side of a tile: its slab sums (4 KiB) and picture stay in the core's cache.
  static constexpr int kTile = 16;
  static constexpr int kPixels = kTile * kTile;
  // The records and bins a frame holds at once, at most about (passBudget): kPassBytesPerSplat
  // a splat, but never less than kPassBytesLeast nor more than kPassBytes. A frame that would
  // take more in one pass (its records, their tiles and places, its bins: about 100 bytes a
  // splat) goes in passes of fewer slabs. Passes cost time (each tile's state is put away and
  // taken up again, a splat reaching two passes has a record in each), so a small frame takes
  // one. The estimate takes 1.75 tiles an entry, and larger footprints reach more: 26 bytes a
  // splat estimated held 24-26 on the shared volumes' default views at 512² and 1024², a margin
  // under 32.
  static constexpr size_t kPassBytes = size_t(256) << 20;
  static constexpr size_t kPassBytesLeast = size_t(16) << 20;
  static constexpr size_t kPassBytesPerSplat = 26;
  static size_t passBudget(size_t splats) {
    return std::clamp(kPassBytesPerSplat * splats, kPassBytesLeast, kPassBytes);
  }

  // A slab entry listed for a tile: its record's place in the pass with SlabPartition's
  // first/last-slab flags, and its slab.
  struct Item {
    uint32_t entry;
    uint32_t slab;
  };

  // The items of a run of the pass's slabs, tile by tile, each tile's in slab order: tile t's
  // are items[start[t]] up to items[start[t + 1]].
  struct Run {
    std::vector<uint32_t> start;
    std::vector<Item, DefaultInitAllocator<Item>> items;  // each written once binned
    size_t count(size_t tile) const { return start[tile + 1] - start[tile]; }
  };

  // What a tile keeps from one pass to the next (its picture stays in the picture): the pixels
  // still taking slabs, their constants along the ray, the slab composited last and its values.
  struct TileState {
    bool begun = false;  // the pixels' constants are set
    bool done = false;   // no pixel takes more slabs
    uint32_t previous = UINT32_MAX;
    alignas(32) float live[kPixels];      // 1 where the pixel is in the picture and takes more
    alignas(32) float keptNear[kPixels];  // the clip region along the ray
    alignas(32) float keptFar[kPixels];
    alignas(32) float boxNear[kPixels];  // post: the data's box along the ray
    alignas(32) float boxFar[kPixels];
    alignas(32) float stretch[kPixels];
    alignas(32) float last[kPixels];  // post: the slab composited last's nearest value
    bool hasLast[kPixels];
  };

  struct Timing {
    double recordsMs = 0.0;
    double binMs = 0.0;
    double compositeMs = 0.0;
    size_t entries = 0;  // (slab entry, tile) pairs binned
    size_t bytes = 0;    // the records, their places and the bins at their largest
  };
  // Draws the picture of the splats `records` makes from the slab lists `order` and `slabs`
  // (SlabPartition's, front to back) into `picture`, width x height, rows bottom up (y up, as
  // the GL's images): composite, premultiplied colour and opacity over nothing; X-ray, the
  // summed optical depth in alpha; MIP, the largest weighted value in red (the slab image the
  // final pass reads). Each pass makes the records of its entries, bins them and gathers the
  // tiles not done. Once `cancel` (if given) is set the passes and tiles not begun are left.
  Timing draw(const SplatRecordMaker& records, const std::vector<uint32_t>& order,
              const std::vector<Slab>& slabs, const TileCompositeSettings& settings,
              std::vector<glm::vec4>& picture, const std::atomic<bool>* cancel = nullptr);
  // Test hook: false draws with the build's baseline composite even where the machine runs its
  // AVX2 and FMA build (tile_compositor_avx2.cpp), to hold the two equal.
  void setAvx2(bool allowed) { avx2Allowed_ = allowed; }
  // Test hooks: the bytes a pass may hold (0: passBudget), or the slab-grid steps a pass spans
  // (0: from the bytes).
  void setPassBytes(size_t bytes) { passBytes_ = bytes; }
  void setPassSlabs(size_t steps) { passSlabs_ = steps; }

 private:
  // Kept between passes and frames (their capacity).
  std::vector<SplatRecord> records_;  // the pass's, one a splat, in place order
  // Written whole each pass, so resized without being zeroed (DefaultInitAllocator).
  std::vector<uint32_t, DefaultInitAllocator<uint32_t>> splatsOf_;  // the splat at each place
  struct TileRect {
    uint16_t x0, y0, x1, y1;  // the tiles a record's box reaches, inclusive (x0 > x1: none)
  };
  std::vector<TileRect, DefaultInitAllocator<TileRect>> rects_;  // each place's
  std::vector<uint32_t> places_;                                 // each splat's place in the pass
  // Filled in parallel, one run a task: a tile reads its runs in turn, front to back.
  std::vector<Run> bins_;
  std::vector<TileState> tiles_;
  bool avx2Allowed_ = true;
  size_t passBytes_ = 0;
  size_t passSlabs_ = 0;
  // `border`: pixels about a tile whose kernels it takes too (field normals' neighbours).
  void makeRecords(const SplatRecordMaker& maker, const std::vector<uint32_t>& order,
                   const std::vector<Slab>& slabs, size_t first, size_t end, int width, int height,
                   int border);
  void bin(const std::vector<uint32_t>& order, const std::vector<Slab>& slabs, size_t first,
           size_t end, int width, int height);
};

}  // namespace ewa
