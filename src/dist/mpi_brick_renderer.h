// BrickRenderer: one rank's splat renderer on its own headless context, kept across frames.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/splat_attributes.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "gl/shader_library.h"
#include "platform/gl_context.h"
#include "render/renderer.h"
#include "render/splat_renderer.h"

namespace ewa::dist {

class BrickRenderer {
 public:
  // A headless context of `backend` ("auto", "egl", "osmesa") and the splat renderer on it.
  // Throws when either cannot be made.
  BrickRenderer(const std::string& backend, const std::string& shaderDir);
  // Where BrickRenderers made after this call get their context instead (null: headless ones):
  // the window's rank makes its brick's a hidden window of the window's GL, since an OSMesa
  // context beside a GLX window does not load every GL 4.5 function, and an EGL one may not be
  // made current beside it.
  using ContextFactory = std::function<std::unique_ptr<platform::GlContext>()>;
  static void setContextFactory(ContextFactory factory);
  ~BrickRenderer();
  BrickRenderer(const BrickRenderer&) = delete;
  BrickRenderer& operator=(const BrickRenderer&) = delete;

  // The volume the next frames draw, held by the caller until the next call; its splats must
  // come with the next render.
  void setVolume(const Volume& volume);
  // Draws the volume under `tf` and returns the frame's picture (readFramePicture: premultiplied
  // RGBA floats, bottom row first). Composite slabs lie on the grid through `slabAnchor` (NaN: the
  // renderer's own). `splats`: the volume's splats classified under `tf` already (taken), or null
  // to keep the renderer's own.
  std::vector<float> render(const TransferFunction& tf, const Camera& camera,
                            const RenderSettings& settings, int width, int height,
                            double slabAnchor, ClassifiedSplats* splats);
  // The splats the last frame drew (their classification's), for the slab grid's anchor.
  const SplatRenderer& splatRenderer() const { return *splat_; }
  const std::string& note() const { return note_; }
  // The last frame's statistics (splats, slabs, which splatter).
  const RenderStats& stats() const { return stats_; }

 private:
  std::unique_ptr<platform::GlContext> context_;
  gl::ShaderLibrary shaders_;
  std::unique_ptr<Renderer> renderer_;
  SplatRenderer* splat_ = nullptr;
  std::string note_;
  RenderStats stats_;
};

}  // namespace ewa::dist
