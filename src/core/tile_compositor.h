// TileCompositor: the CPU splatter's composite, in the compute tiles' shape
// (shaders/tile_ewa.comp.glsl): screen tiles, each slab entry binned to the tiles its box
// reaches in slab order, each tile's slabs added up, composited front to back and left once
// every pixel is opaque, one tile a task over all cores.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "core/camera.h"
#include "core/clip_region.h"
#include "core/ewa_footprint.h"
#include "core/slab_partition.h"
#include "core/splat_records.h"
#include "core/volume.h"

namespace ewa {

// What a tile's pixels gather (the splat shaders' variants): pre-classified optical depth and
// colour composited slab by slab; post-classified kernel-weighted values classified per pixel
// (TileCompositeSettings::samples); X-ray's summed optical depth; MIP's largest weighted value.
enum class TileGather { Pre, Post, XRay, Mip };

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
  // Test hook: every pixel takes a kernel's slab shares at the kernel centre's depth (its
  // depth slopes dropped), a wrong slab split that the tests must catch.
  bool flatDepths = false;
};

class TileCompositor {
 public:
  // Pixels a side of a tile: its slab sums (4 KiB) and picture stay in the core's cache.
  static constexpr int kTile = 16;

  // A slab entry listed for a tile: the splat index with SlabPartition's first/last-slab flags,
  // and its slab.
  struct Item {
    uint32_t entry;
    uint32_t slab;
  };

  struct Timing {
    double binMs = 0.0;
    double compositeMs = 0.0;
    size_t entries = 0;  // (slab entry, tile) pairs binned
  };
  // Draws the picture of `records` (one per splat) from the slab lists `order` and `slabs`
  // (SlabPartition's, front to back) into `picture`, width x height, rows bottom up (y up, as
  // the GL's images): composite, premultiplied colour and opacity over nothing; X-ray, the
  // summed optical depth in alpha; MIP, the largest weighted value in red (the slab image the
  // final pass reads).
  // Once `cancel` (if given) is set the tiles not begun are left empty.
  Timing draw(const std::vector<SplatRecord>& records, const std::vector<uint32_t>& order,
              const std::vector<Slab>& slabs, const TileCompositeSettings& settings,
              std::vector<glm::vec4>& picture, const std::atomic<bool>* cancel = nullptr);
  // Test hook: false draws with the build's baseline composite even where the machine runs its
  // AVX2 and FMA build (tile_compositor_avx2.cpp), to hold the two equal.
  void setAvx2(bool allowed) { avx2Allowed_ = allowed; }

 private:
  // Lists per run of slabs (bins_[run][tile]), filled in parallel, one run a task, each in slab
  // order: a tile reads its runs in turn, front to back. Kept between frames (their capacity).
  std::vector<std::vector<std::vector<Item>>> bins_;
  bool avx2Allowed_ = true;
  void bin(const std::vector<SplatRecord>& records, const std::vector<uint32_t>& order,
           const std::vector<Slab>& slabs, int width, int height);
};

}  // namespace ewa
