// SplatRenderer: EWA (and Swan and plain) volume splatting with view-aligned slab compositing.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>

#include "core/slab_partition.h"
#include "core/splat_set.h"
#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "render/render_targets.h"
#include "render/renderer.h"

namespace ewa {

class SplatRenderer : public Renderer {
 public:
  // Builds the shader programs; a GL 4.5 context must be current. Throws gl::GlError.
  explicit SplatRenderer(const gl::ShaderLibrary& shaders);

  void setVolume(const Volume& volume) override;
  void setTransferFunction(const TransferFunction& tf) override;
  void render(const Camera& camera, const RenderSettings& settings, int width,
              int height) override;
  Image8 readImage() const override;
  unsigned outputTexture() const override { return targets_.output.id(); }
  RenderStats stats() const override { return stats_; }

  // X-ray mode only: the summed optical depth per pixel, bottom row first (for tests).
  std::vector<float> readOpticalDepth() const;
  // The splats of the current volume and transfer function (built on the next render()).
  const SplatSet& splats() const { return splats_; }
  // The largest point size this GL draws; bigger footprints go through the quad path.
  float pointSizeLimit() const { return pointSizeLimit_; }
  // Test hook: a lower limit forces the quad path (never above the GL limit).
  void setPointSizeLimit(float limit);
  // Test hook: fewer splats allowed than the GL limit, to test the error without a huge volume.
  void setMaxSplats(size_t maxSplats) { maxSplats_ = std::min(glMaxSplats_, maxSplats); }

 private:
  void rebuildSplats();
  void setCommonUniforms(gl::Program& program, const Camera& camera, const Projection& proj,
                         const RenderSettings& settings);
  void drawSplats(const Slab& slab, bool quads);
  double footprintRadiusBound(const Projection& proj, const RenderSettings& settings,
                              double nearestDepth) const;

  const Volume* volume_ = nullptr;
  TransferFunction tf_;
  bool splatsDirty_ = true;
  SplatSet splats_;
  SlabPartition partition_;

  gl::Program pointProgram_;
  gl::Program quadProgram_;
  gl::Program slabProgram_;
  gl::Program finalProgram_;
  gl::VertexArray emptyVao_;
  gl::Buffer splatBuffer_;
  gl::Buffer orderBuffer_;
  gl::Texture transferTexture_;
  RenderTargets targets_;
  size_t glMaxSplats_ = SIZE_MAX;        // splats that fit the GPU's storage block and memory
  size_t maxSplats_ = SIZE_MAX;          // the limit in force (lower in tests)
  uint64_t maxStorageBlockBytes_ = 0;    // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  float pointSizeLimit_ = 64.0f;
  float glPointSizeLimit_ = 64.0f;
  RenderStats stats_;
};

}  // namespace ewa
