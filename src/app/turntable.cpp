// Headless turntables: one renderer, N cameras, N PNGs written atomically.
#include "app/turntable.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "gl/shader_library.h"
#include "io/frame_names.h"
#include "io/png_io.h"
#include "io/terminal_progress.h"
#include "platform/headless_context.h"
#include "render/splat_renderer.h"

namespace ewa {

void renderTurntable(const Scene& scene, const Options& o) {
  const int count = o.turntable;
  if (count < 1) throw std::invalid_argument("--turntable: needs at least 1 frame");
  const FrameNaming naming = parseFrameNaming(o.output);
  // The folder (or the pattern's folder) is made up front, so a bad path fails before rendering.
  const std::filesystem::path folder =
      naming.pattern ? std::filesystem::path(frameFileName(naming, 0, count)).parent_path()
                     : std::filesystem::path(naming.text);
  if (!folder.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (!std::filesystem::is_directory(folder))
      throw std::runtime_error(folder.string() + ": cannot create the turntable folder");
  }
  auto context = platform::createHeadlessContext(platform::parseHeadlessBackend(o.backend));
  const gl::ShaderLibrary shaders(o.shaderDir);
  SplatRenderer renderer(shaders);
  renderer.setVolume(scene.volume);
  renderer.setTransferFunction(scene.transferFunction);
  const Camera start = initialCamera(scene.volume, o);
  TerminalProgress progress("ewaview: turntable");
  const auto begin = std::chrono::steady_clock::now();
  for (int f = 0; f < count; ++f) {
    const std::string file = frameFileName(naming, f, count);
    progress.update(f + 1, count, file);
    renderer.render(turntableCamera(start, f, count), o.render, o.width, o.height);
    writePng(file, renderer.readImage());
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  char note[96];
  std::snprintf(note, sizeof note, "%d frames in %.1f s", count, s);
  progress.finish(note);
}

}  // namespace ewa
