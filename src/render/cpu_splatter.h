// CpuSplatter: the splat renderer's frame splatted on the CPU (core/splat_records.h,
// core/tile_compositor.h: the footprint, reach and slab split C++ the shaders mirror), its
// picture handed to the GL as the texture the final pass reads.
#pragma once

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

// Whether the CPU splatter draws frames under `settings`: every mode and order, pre-classified
// and post-classified unshaded (shaded post-classification is rasterized). `why`: the reason
// it does not, for RenderStats::note.
bool cpuSplatterDraws(const RenderSettings& settings, std::string* why = nullptr);

// The splat programs' per-frame state (SplatRenderer::setCommonUniforms) for `volume` seen by
// `volumeCamera` (in the volume's own frame) through `proj` under `settings`, with the
// partition's `reach` and the transfer function's baked table.
SplatFrameSetup cpuSplatSetup(const Volume& volume, const Camera& volumeCamera,
                              const Projection& proj, const RenderSettings& settings,
                              const KernelReach& reach, const std::vector<glm::vec4>& transfer);

// What the tiles gather for `settings`' mode and classification.
TileGather tileGather(const RenderSettings& settings);

class CpuSplatter {
 public:
  struct Timing {
    double recordsMs = 0.0;  // each splat's footprint and colour
    double binMs = 0.0;
    double compositeMs = 0.0;
    double uploadMs = 0.0;  // the picture to its texture
    size_t entries = 0;     // (slab entry, tile) pairs
    double totalMs() const { return recordsMs + binMs + compositeMs + uploadMs; }
  };
  // Draws the frame: the splats' records under `setup`, the partition's slab lists (`order`,
  // `slabs`, front to back) gathered in tiles, post-classified through `tables` with the
  // covered lengths ended at `dataBox` (index coordinates, `cameraToIndex` from camera space),
  // the picture uploaded to pictureTexture() (with `upload`; a GL context must be current).
  Timing draw(const ClassifiedSplats& splats, const std::vector<uint32_t>& order,
              const std::vector<Slab>& slabs, const SplatFrameSetup& setup,
              const RenderSettings& settings, const TileClassifyTables& tables,
              const glm::dmat4& cameraToIndex, const DataBox& dataBox, bool upload = true,
              bool flatDepths = false);
  // The last picture (TileCompositor::draw's): composite, premultiplied RGBA over nothing;
  // X-ray and MIP, the slab image the final pass reads; rows bottom up.
  const std::vector<glm::vec4>& picture() const { return picture_; }
  const gl::Texture& pictureTexture() const { return texture_; }
  size_t bytes() const;

 private:
  std::vector<SplatRecord> records_;
  TileCompositor compositor_;
  std::vector<glm::vec4> picture_;
  gl::Texture texture_;
  int width_ = 0, height_ = 0;
};

}  // namespace ewa
