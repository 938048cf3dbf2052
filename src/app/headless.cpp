// Headless rendering: context, renderer, one frame, PNG.
#include "app/headless.h"

#include <memory>
#include <stdexcept>

#include "gl/shader_library.h"
#include "io/atomic_file.h"
#include "io/png_io.h"
#include "platform/headless_context.h"
#include "render/renderer_factory.h"

namespace ewa {

void renderHeadless(const Scene& scene, const Options& o) {
  // The picture replaces whatever --output names, but never one of the files being read.
  for (const std::string& input : {o.file, o.tfFile}) {
    if (!input.empty() && sameExistingFile(o.output, input))
      throw std::runtime_error(o.output + ": is an input file; refusing to overwrite it");
  }
  auto context = platform::createHeadlessContext(platform::parseHeadlessBackend(o.backend));
  const gl::ShaderLibrary shaders(o.shaderDir);
  const std::unique_ptr<Renderer> renderer = createRenderer(o.render.renderer, shaders);
  renderer->setVolume(scene.volume);
  renderer->setTransferFunction(scene.transferFunction);
  renderer->render(initialCamera(scene.volume, o), o.render, o.width, o.height);
  writePng(o.output, renderer->readImage());
}

}  // namespace ewa
