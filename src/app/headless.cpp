// Headless rendering: context, renderer, one frame, PNG.
#include "app/headless.h"

#include <memory>

#include "gl/shader_library.h"
#include "io/png_io.h"
#include "platform/headless_context.h"
#include "render/renderer_factory.h"

namespace ewa {

void renderHeadless(const Scene& scene, const Options& o) {
  auto context = platform::createHeadlessContext(platform::parseHeadlessBackend(o.backend));
  const gl::ShaderLibrary shaders(o.shaderDir);
  const std::unique_ptr<Renderer> renderer = createRenderer(o.render.renderer, shaders);
  renderer->setVolume(scene.volume);
  renderer->setTransferFunction(scene.transferFunction);
  renderer->render(initialCamera(scene.volume, o), o.render, o.width, o.height);
  writePng(o.output, renderer->readImage());
}

}  // namespace ewa
