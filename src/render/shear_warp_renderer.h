// ShearWarpRenderer: the CPU shear-warp renderer behind the Renderer interface.
#pragma once

#include "core/shear_warp.h"
#include "gl/texture.h"
#include "render/renderer.h"

namespace ewa {

// Composites and warps on the CPU (core/shear_warp.h), then uploads the picture to an RGBA8
// texture so the window can draw it like the splat renderer's. Parallel and perspective views;
// a perspective view whose intermediate image would be too large (a wide view from
// near or inside the volume) is drawn as the orthographic view of the same height at the focal
// point, and stats().note says so.
class ShearWarpRenderer : public Renderer {
 public:
  // A GL context must be current (for the output texture).
  ShearWarpRenderer() = default;

  void setVolume(const Volume& volume) override;
  void setTransferFunction(const TransferFunction& tf) override;
  void render(const Camera& camera, const RenderSettings& settings, int width, int height) override;
  Image8 readImage() const override { return image_; }
  unsigned outputTexture() const override { return texture_.id(); }
  RenderStats stats() const override { return stats_; }

  const ShearWarpStats& shearWarpStats() const { return core_.stats(); }
  ShearWarp& core() { return core_; }

 private:
  ShearWarp core_;
  Image8 image_;
  gl::Texture texture_;
  RenderStats stats_;
};

}  // namespace ewa
