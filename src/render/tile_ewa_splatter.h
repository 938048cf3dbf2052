// TileEwaSplatter: pre-classified EWA splatting in compute tiles (shaders/tile_ewa.comp.glsl),
// slab by slab with the splat renderer's footprints and slab lists, for the benchmarks: what a
// compute splatter would cost beside the rasterizer's frame, and that it draws the same picture.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "render/tile_bins.h"

namespace ewa {

// One splat as shaders/tile_ewa.comp.glsl reads it: (centre x, centre y, half width, half
// height) in pixels (y up, pixel centres at +0.5); (conic xx, xy, yy, optical depth at the
// centre: mass times the footprint's peak); (camera depth, depth slope per pixel x and y, depth
// sigma); (colour rgb, 0).
struct TileEwaSplat {
  glm::vec4 box;
  glm::vec4 conic;
  glm::vec4 depth;
  glm::vec4 color;
};

// What one frame draws: the splats, the slab entries in slab order as SlabPartition lists them
// (splat index with its first/last-slab flags, then the slab's number) and each slab's near and
// far camera depth.
struct TileEwaFrame {
  std::vector<TileEwaSplat> splats;
  std::vector<glm::uvec2> entries;
  std::vector<glm::vec2> slabDepths;
  float cutoff = 5.0f;
  glm::vec2 depthProfile{1e30f, 1.0f};  // DepthProfile (erfReach, scale)
  float termination = 0.99f;
};

class TileEwaSplatter {
 public:
  // `tileSize`: pixels a side of a tile (one work group), 8 or 16.
  TileEwaSplatter(const gl::ShaderLibrary& shaders, int tileSize);
  // Uploads the frame's splats, entries and slabs; not part of the timed draw.
  void setFrame(const TileEwaFrame& frame);

  struct Timing {
    double binMs = 0.0;        // bucket counts, their scan and the lists
    double compositeMs = 0.0;  // the tiles' slabs added up and composited
    size_t entries = 0;        // (slab entry, tile) pairs
    double totalMs() const { return binMs + compositeMs; }
  };
  // Draws a width x height picture (premultiplied colour and opacity over nothing, RGBA32F),
  // waiting for the GPU after each stage.
  Timing draw(int width, int height);
  // The last draw's picture, rows bottom up.
  std::vector<glm::vec4> picture() const;
  // The splat records setFrame uploaded, for a GPU pass to overwrite with its own
  // (SplatRenderer::writeTileSplats) before the next draw.
  gl::Buffer& splatBuffer() { return splats_; }

 private:
  int tileSize_;
  gl::Program countPass_, scanPass_, scatterPass_, compositePass_;
  gl::Buffer splats_, entries_, slabs_;
  TileBins bins_{"tile EWA buffers"};  // each slab entry listed in its (tile, slab) buckets
  gl::Texture picture_;
  TileEwaFrame settings_;  // the frame's scalars (its vectors are uploaded, then dropped)
  size_t entryCount_ = 0, slabCount_ = 0;
};

}  // namespace ewa
