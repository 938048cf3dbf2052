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
  renderer_.reset();
}

Image8 HeadlessSession::render(const Volume& volume, const TransferFunction& tf,
                               const Camera& camera, const RenderSettings& settings, int width,
                               int height) {
  context_->makeCurrent();
  if (!renderer_ || kind_ != settings.renderer) {
    renderer_.reset();
    renderer_ = createRenderer(settings.renderer, shaders_);
    kind_ = settings.renderer;
    volume_ = nullptr;
    tfSet_ = false;
  }
  if (volume_ != &volume) {
    renderer_->setVolume(volume);
    volume_ = &volume;
  }
  if (!tfSet_ || tf != tf_) {
    renderer_->setTransferFunction(tf);
    tf_ = tf;
    tfSet_ = true;
  }
  renderer_->render(camera, settings, width, height);
  const std::string note = renderer_->stats().note;
  if (note != lastNote_) newNote_ = note;  // said once while it holds
  lastNote_ = note;
  Image8 image = renderer_->readImage();
  if (axes_)
    drawStrokes(image, orientationAxes(camera.rotation(), volume.patientFrame(),
                                       axesPlacement(image.width, image.height)));
  return image;
}

std::string HeadlessSession::takeNote() {
  std::string note;
  note.swap(newNote_);
  return note;
}

}  // namespace ewa
