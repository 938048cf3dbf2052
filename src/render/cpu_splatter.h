// CpuSplatter: the splat renderer's frame splatted on the CPU (core/splat_records.h,
// core/tile_compositor.h: the footprint, reach and slab split C++ the shaders mirror), its
// picture handed to the GL as the texture the final pass reads.
#pragma once

#include <atomic>
#include <glm/vec4.hpp>
#include <vector>

#include "core/camera.h"
#include "core/slab_partition.h"
#include "core/splat_attributes.h"
#include "core/splat_records.h"
#include "core/tile_compositor.h"
#include "gl/texture.h"
#include "render/renderer.h"

namespace ewa {

// The splat programs' per-frame state (SplatRenderer::setCommonUniforms) for `volume` seen by
// `volumeCamera` (in the volume's own frame) through `proj` under `settings`, with the
// partition's `reach` and the transfer function's baked table.
SplatFrameSetup cpuSplatSetup(const Volume& volume, const Camera& volumeCamera,
                              const Projection& proj, const RenderSettings& settings,
                              const KernelReach& reach, const std::vector<glm::vec4>& transfer);

// The normals post-classified tiles are lit by under `settings` (None: unshaded).
TileNormals tileNormals(const RenderSettings& settings);

// What the tiles gather for `settings`' mode and classification.
TileGather tileGather(const RenderSettings& settings);

// The tiles' settings for a frame of `setup` under `settings`, post-classified through
// `tables` with the covered lengths ended at `dataBox` (index coordinates, `cameraToIndex`
// from camera space); ray normals need `gradients` set besides.
TileCompositeSettings cpuCompositeSettings(const SplatFrameSetup& setup,
                                           const RenderSettings& settings,
                                           const TileClassifyTables& tables,
                                           const glm::dmat4& cameraToIndex, const DataBox& dataBox);

class CpuSplatter {
 public:
  struct Timing {
    double recordsMs = 0.0;  // each splat's footprint and colour
    double binMs = 0.0;
    double compositeMs = 0.0;
    double uploadMs = 0.0;  // the picture to its texture
    size_t entries = 0;     // (slab entry, tile) pairs
    size_t bytes = 0;       // the records and tile bins at their largest
    double totalMs() const { return recordsMs + binMs + compositeMs + uploadMs; }
  };
  // Draws the frame on the CPU without GL (from any thread): the splats' records under
  // `setup`, the partition's slab lists (`order`, `slabs`, front to back) gathered in tiles
  // under `composite` (cpuCompositeSettings) into picture(). Stops early, the picture
  // unfinished, once `cancel` (if given) is set.
  Timing compute(const ClassifiedSplats& splats, const std::vector<uint32_t>& order,
                 const std::vector<Slab>& slabs, const SplatFrameSetup& setup,
                 const TileCompositeSettings& composite, const std::atomic<bool>* cancel = nullptr);
  // The picture to pictureTexture() (a GL context must be current); its milliseconds.
  double upload();
  // The last picture (TileCompositor::draw's): composite, premultiplied RGBA over nothing;
  // X-ray and MIP, the slab image the final pass reads; rows bottom up.
  const std::vector<glm::vec4>& picture() const { return picture_; }
  const gl::Texture& pictureTexture() const { return texture_; }
  size_t bytes() const;

 private:
  TileCompositor compositor_;
  std::vector<glm::vec4> picture_;
  gl::Texture texture_;
  int width_ = 0, height_ = 0;                // the picture's
  int textureWidth_ = 0, textureHeight_ = 0;  // the texture's
};

}  // namespace ewa
