// HeadlessSession: an off-screen context and the renderer the settings name, reused across frames.
#pragma once

#include <memory>
#include <string>

#include "core/camera.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "gl/shader_library.h"
#include "io/png_io.h"
#include "platform/gl_context.h"
#include "render/renderer.h"

namespace ewa {

// Every headless picture (--output, --turntable, the Python module) comes from here, so each
// honours --renderer: the renderer is made by createRenderer and remade when the kind changes.
class HeadlessSession {
 public:
  // Creates the context ("osmesa" or "egl"); throws ContextError / std::invalid_argument.
  HeadlessSession(const std::string& backend, const std::string& shaderDir);
  ~HeadlessSession();
  HeadlessSession(const HeadlessSession&) = delete;
  HeadlessSession& operator=(const HeadlessSession&) = delete;

  // Renders `volume` (which must stay alive and unchanged while this session may render it)
  // with `tf` from `camera`, and returns the RGB picture, top row first; with the orientation
  // axes in its corner after setAxes(true).
  Image8 render(const Volume& volume, const TransferFunction& tf, const Camera& camera,
                const RenderSettings& settings, int width, int height);
  // Whether render() draws the orientation axes (--axis).
  void setAxes(bool on) { axes_ = on; }
  // The statistics of the last render (empty before the first).
  RenderStats stats() const { return renderer_ ? renderer_->stats() : RenderStats{}; }
  // The renderer's RenderStats::note (why a frame was not drawn as asked) when a render has
  // brought a new one since the last call, else empty: each note said once while it holds.
  std::string takeNote();

 private:
  std::unique_ptr<platform::GlContext> context_;
  gl::ShaderLibrary shaders_;
  std::unique_ptr<Renderer> renderer_;
  RendererKind kind_ = RendererKind::Splat;
  const Volume* volume_ = nullptr;  // what renderer_ was given, to skip repeated uploads
  TransferFunction tf_;
  bool tfSet_ = false;
  bool axes_ = false;
  std::string lastNote_;  // the last render's RenderStats::note
  std::string newNote_;   // one that appeared since takeNote last took it
};

}  // namespace ewa
