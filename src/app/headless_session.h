// HeadlessSession: an off-screen context and the renderer the settings name, reused across frames.
#pragma once

#include <memory>
#include <string>
#include <vector>

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
  // The same without the axes, by the renderer of `slot` (0, 1, ...): each slot keeps its own
  // renderer, volume and transfer function, so the channels of an overlay (scene_render.h) are
  // not uploaded again for every frame.
  Image8 renderBare(const Volume& volume, const TransferFunction& tf, const Camera& camera,
                    const RenderSettings& settings, int width, int height, size_t slot = 0);
  // Draws the orientation axes on `image` after setAxes(true), as render() does.
  void drawAxes(Image8& image, const Camera& camera, const Volume& volume) const;
  // Whether render() draws the orientation axes (--axis).
  void setAxes(bool on) { axes_ = on; }
  // The statistics of the last render by `slot` (empty before the first).
  RenderStats stats(size_t slot = 0) const {
    return slot < slots_.size() && slots_[slot].renderer ? slots_[slot].renderer->stats()
                                                         : RenderStats{};
  }
  // The renderer's RenderStats::note (why a frame was not drawn as asked) when a render has
  // brought a new one since the last call, else empty: each note said once while it holds.
  std::string takeNote();

 private:
  std::unique_ptr<platform::GlContext> context_;
  gl::ShaderLibrary shaders_;
  struct Slot {
    std::unique_ptr<Renderer> renderer;
    RendererKind kind = RendererKind::Splat;
    const Volume* volume = nullptr;  // what the renderer was given, to skip repeated uploads
    TransferFunction tf;
    bool tfSet = false;
    std::string lastNote;  // its last render's RenderStats::note
  };
  std::vector<Slot> slots_;
  bool axes_ = false;
  std::string newNote_;  // a note that appeared since takeNote last took it
};

}  // namespace ewa
