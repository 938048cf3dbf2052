// TileSplatBaseline: footprints added up by compute tiles instead of rasterized point sprites,
// the benchmarks' measure of what a compute splatter would cost beside SpriteBaseline.
#pragma once

#include <glm/vec4.hpp>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "render/tile_bins.h"

namespace ewa {

// One footprint as shaders/tile_splat.comp.glsl reads it: (centre x, centre y, half width,
// half height) in pixels (y up, pixel centres at +0.5), then (conic xx, xy, yy, peak).
struct TileFootprint {
  glm::vec4 box;
  glm::vec4 conic;
};

class TileSplatBaseline {
 public:
  // `tileSize`: pixels a side of a tile (one work group), 8 or 16.
  TileSplatBaseline(const gl::ShaderLibrary& shaders, int tileSize);
  // Uploads the footprints, cut off at r = `cutoff`; not part of the timed draw.
  void setFootprints(const std::vector<TileFootprint>& footprints, float cutoff);

  struct Timing {
    double binMs = 0.0;         // tile counts, their scan and the tile lists
    double accumulateMs = 0.0;  // the per-tile sums stored in the two images
    size_t entries = 0;         // (footprint, tile) pairs
    double totalMs() const { return binMs + accumulateMs; }
  };
  // Bins and adds up every footprint into two width x height images, RGBA16F with `halfFloat`
  // else RGBA32F (as a slab with four samples has), waiting for the GPU after each stage.
  Timing draw(int width, int height, bool halfFloat);
  // The first image of the last draw: per pixel (0.5 w, w, 0.25 w, w) summed over the
  // footprints, w = peak * windowedGaussian(r, cutoff); rows bottom up.
  std::vector<glm::vec4> frontImage() const;

 private:
  int tileSize_;
  gl::Program countPass_, scanPass_, scatterPass_, accumulateHalf_, accumulateFloat_;
  gl::Buffer footprints_;
  TileBins bins_{"tile splat buffers"};  // each footprint listed in the tiles it reaches
  gl::Texture front_, back_;
  size_t count_ = 0;
  float cutoff_ = 4.0f;
};

}  // namespace ewa
