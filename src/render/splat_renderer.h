// SplatRenderer: EWA (and Swan and plain) volume splatting with view-aligned slab compositing.
#pragma once

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

  // Live transfer-function editing (kept apart from the drawing code): uploads `tf`'s table to
  // the GPU now and keeps the current splats, so the next render shows the new colours and
  // opacities without classifying the volume again. Voxels the new function makes visible
  // appear once a matching set comes through setSplats(). Needs setVolume() first.
  void updateTransferTexture(const TransferFunction& tf);
  // Replaces the splats with a set built elsewhere (e.g. AsyncSplatBuilder) for the current
  // volume and uploads it; the next render draws it.
  void setSplats(SplatSet splats);

  // X-ray mode only: the summed optical depth per pixel, bottom row first (for tests).
  std::vector<float> readOpticalDepth() const;
  // The splats of the current volume and transfer function (built on the next render()).
  const SplatSet& splats() const { return splats_; }
  // The largest point size this GL draws; bigger footprints go through the quad path.
  float pointSizeLimit() const { return pointSizeLimit_; }
  // Test hook: a lower limit forces the quad path (never above the GL limit).
  void setPointSizeLimit(float limit);

 private:
  void rebuildSplats();
  void uploadTransferTexture();
  void uploadSplats();
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
  float pointSizeLimit_ = 64.0f;
  float glPointSizeLimit_ = 64.0f;
  RenderStats stats_;
};

}  // namespace ewa
