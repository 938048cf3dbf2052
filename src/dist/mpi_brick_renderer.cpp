// BrickRenderer: a rank's headless splat renderer; volume and splats are set when they change.
#include "dist/mpi_brick_renderer.h"

#include <stdexcept>
#include <utility>

#include "platform/headless_context.h"
#include "render/renderer_factory.h"

namespace ewa::dist {

namespace {

BrickRenderer::ContextFactory& contextFactory() {
  static BrickRenderer::ContextFactory factory;
  return factory;
}

}  // namespace

void BrickRenderer::setContextFactory(ContextFactory factory) {
  contextFactory() = std::move(factory);
}

BrickRenderer::BrickRenderer(const std::string& backend, const std::string& shaderDir)
    : context_(contextFactory()
                   ? contextFactory()()
                   : platform::createHeadlessContext(platform::parseHeadlessBackend(backend))),
      shaders_(shaderDir) {
  context_->makeCurrent();
  renderer_ = createRenderer(RendererKind::Splat, shaders_);
  splat_ = dynamic_cast<SplatRenderer*>(renderer_.get());
  if (!splat_) throw std::runtime_error("the splat renderer is not available");
}

BrickRenderer::~BrickRenderer() {
  context_->makeCurrent();
  renderer_.reset();
}

void BrickRenderer::setVolume(const Volume& volume) {
  context_->makeCurrent();
  renderer_->setVolume(volume);
}

std::vector<float> BrickRenderer::render(const TransferFunction& tf, const Camera& camera,
                                         const RenderSettings& settings, int width, int height,
                                         double slabAnchor, ClassifiedSplats* splats) {
  context_->makeCurrent();
  splat_->setSlabAnchor(slabAnchor);
  // Splats classified already (to find the brick's nearest kernel) are not classified again.
  // As the renderer's own classification does: the transfer table first, then the splats.
  if (splats) {
    renderer_->setTransferFunction(tf);
    splat_->updateTransferTexture(tf);
    splat_->setSplats(std::move(*splats), splatClassification(settings));
  }
  renderer_->render(camera, settings, width, height);
  stats_ = renderer_->stats();
  note_ = stats_.note;
  return splat_->readFramePicture();
}

}  // namespace ewa::dist
