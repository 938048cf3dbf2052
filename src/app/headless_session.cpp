// HeadlessSession: context first, then shaders and the factory's renderer; GL objects go first.
#include "app/headless_session.h"

#include "core/orientation_axes.h"
#include "platform/headless_context.h"
#include "render/renderer_factory.h"

namespace ewa {

HeadlessSession::HeadlessSession(const std::string& backend, const std::string& shaderDir)
    : context_(platform::createHeadlessContext(platform::parseHeadlessBackend(backend))),
      shaders_(shaderDir) {}

HeadlessSession::~HeadlessSession() {
  // Another session's context may be current (Python keeps several): GL objects die in ours.
  context_->makeCurrent();
  slots_.clear();
}

Image8 HeadlessSession::render(const Volume& volume, const TransferFunction& tf,
                               const Camera& camera, const RenderSettings& settings, int width,
                               int height) {
  Image8 image = renderBare(volume, tf, camera, settings, width, height);
  drawAxes(image, camera, volume);
  return image;
}

Image8 HeadlessSession::renderBare(const Volume& volume, const TransferFunction& tf,
                                   const Camera& camera, const RenderSettings& settings, int width,
                                   int height, size_t slot) {
  context_->makeCurrent();
  if (slots_.size() <= slot) slots_.resize(slot + 1);
  Slot& s = slots_[slot];
  if (!s.renderer || s.kind != settings.renderer) {
    s.renderer.reset();
    s.renderer = createRenderer(settings.renderer, shaders_);
    s.kind = settings.renderer;
    s.volume = nullptr;
    s.tfSet = false;
  }
  if (s.volume != &volume) {
    s.renderer->setVolume(volume);
    s.volume = &volume;
  }
  if (!s.tfSet || tf != s.tf) {
    s.renderer->setTransferFunction(tf);
    s.tf = tf;
    s.tfSet = true;
  }
  s.renderer->render(camera, settings, width, height);
  const std::string note = s.renderer->stats().note;
  if (note != s.lastNote && !note.empty()) newNote_ = note;  // said once while it holds
  s.lastNote = note;
  return s.renderer->readImage();
}

void HeadlessSession::drawAxes(Image8& image, const Camera& camera, const Volume& volume) const {
  if (axes_)
    drawStrokes(image, orientationAxes(camera.rotation(), volume.patientFrame(),
                                       axesPlacement(image.width, image.height)));
}

std::string HeadlessSession::takeNote() {
  std::string note;
  note.swap(newNote_);
  return note;
}

}  // namespace ewa
