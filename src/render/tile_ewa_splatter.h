// TileEwaSplatter: EWA splatting in compute tiles (shaders/tile_ewa.comp.glsl; post-classified
// frames composite in shaders/tile_ewa_post.comp.glsl), slab by slab with the splat renderer's
// footprints and slab lists, for the benchmarks: what a compute splatter would cost beside the
// rasterizer's frame, and that it draws the same picture.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "render/gpu_slab_partition.h"
#include "render/tile_bins.h"
#include "render/tile_ewa_programs.h"

namespace ewa {

// One splat as shaders/tile_ewa.comp.glsl reads it: (centre x, centre y, half width, half
// height) in pixels (y up, pixel centres at +0.5); (conic xx, xy, yy, optical depth at the
// centre: mass times the footprint's peak); (camera depth, depth slope per pixel x and y, depth
// sigma); (colour rgb, 0). Post-classified: the weight at the centre in place of the optical
// depth and (colour rgb, normalized value).
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
  // Post-classified, pre-integrated in quarters of each slab, front to back (the splat
  // renderer's default). Either way the caller sets the clip region's (and, post-classified,
  // the classification's) uniforms and textures on compositeProgram()
  // (SplatRenderer::prepareTileComposite). `shading`: with normals from the
  // field's gradient or, `rayNormals`, from the gradient texture along each pixel's ray.
  bool post = false;
  bool shading = false;
  bool rayNormals = false;
};

class TileEwaSplatter {
 public:
  // `tileSize`: pixels a side of a tile (one work group), 8 or 16; its own programs.
  TileEwaSplatter(const gl::ShaderLibrary& shaders, int tileSize);
  // With programs other splatters may share (SplatProgramSet::tiles), of their tile size.
  explicit TileEwaSplatter(std::shared_ptr<TileEwaPrograms> programs);
  // Uploads the frame's splats (none: keeps the records there), entries and slabs; not part of
  // the timed draw.
  void setFrame(const TileEwaFrame& frame);
  // Takes the frame's slab lists from `partition` (built, on the GPU) in place of the frame's
  // entries and slab depths, until the next setFrame: no per-frame list crosses to the GPU.
  // `partition` must outlive the draws.
  void useGpuSlabLists(const GpuSlabPartition& partition);

  struct Timing {
    double binMs = 0.0;        // bucket counts, their scan and the lists
    double compositeMs = 0.0;  // the tiles' slabs added up and composited
    size_t entries = 0;        // (slab entry, tile) pairs
    size_t chunks = 0;         // dispatches of the composite, each a run of slabs
    double totalMs() const { return binMs + compositeMs; }
  };
  // Draws a width x height picture (premultiplied colour and opacity over nothing, RGBA32F),
  // waiting for the GPU after each stage. On a software rasterizer the composite runs in
  // chunks of slabs (compositeChunks).
  Timing draw(int width, int height);
  // Test hook: the loop iterations a tile's run of slabs may reach (compositeChunks); 0: one
  // run of every slab. By default 60000 on a software rasterizer, else 0.
  void setChunkIterations(size_t iterations) { chunkIterations_ = iterations; }
  // The last draw's picture, rows bottom up.
  std::vector<glm::vec4> picture() const;
  const gl::Texture& pictureTexture() const { return picture_; }
  // Bytes of its buffers and images.
  size_t bytes() const;
  // The splat records setFrame uploaded, for a GPU pass to overwrite with its own
  // (SplatRenderer::writeTileSplats) before the next draw.
  gl::Buffer& splatBuffer() { return splats_; }
  // Makes splatBuffer() hold at least `count` records (their contents undefined).
  void reserveSplats(size_t count);
  // The program that composites the frame setFrame took (post-classified: its variant).
  gl::Program& compositeProgram();

 private:
  std::shared_ptr<TileEwaPrograms> programs_;  // of its tile size
  const GpuSlabPartition* gpuLists_ = nullptr;
  gl::Buffer splats_, entries_, slabs_;
  TileBins bins_{"tile EWA buffers"};  // each slab entry listed in its (tile, slab) buckets
  // The composite's dispatches as [first, end) slab runs: one run of every slab, but on
  // llvmpipe, which ends a shader invocation's loops after 65535 iterations in all (then
  // leaving its sums short), runs whose entries bound a tile's iterations below that.
  std::vector<glm::uvec2> compositeChunks() const;

  gl::Texture picture_;
  gl::Texture lastFront_, lastBack_;  // post-classified chunks: the last slab's quarter sums
  size_t chunkIterations_ = 0;
  std::vector<size_t> slabEntries_;  // entries per slab; empty: unknown (one chunk)
  TileEwaFrame settings_;            // the frame's scalars (its vectors are uploaded, then dropped)
  size_t entryCount_ = 0, slabCount_ = 0;
};

}  // namespace ewa
