// ShearWarpRenderer: CPU render, background, 8-bit picture and its GL texture.
#include "render/shear_warp_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/stopwatch.h"
#include "gl/gl_error.h"

namespace ewa {

void ShearWarpRenderer::setVolume(const Volume& volume) {
  core_.setVolume(volume);
}

void ShearWarpRenderer::setTransferFunction(const TransferFunction& tf) {
  core_.setTransferFunction(tf);
}

void ShearWarpRenderer::render(const Camera& camera, const RenderSettings& settings, int width,
                               int height) {
  const auto start = std::chrono::steady_clock::now();
  width = std::max(1, width);
  height = std::max(1, height);
  core_.render(camera, settings.shearWarp, width, height, settings.clip);
  const FloatImage& rgba = core_.image();
  image_.width = width;
  image_.height = height;
  image_.channels = 3;
  image_.pixels.resize(size_t(width) * height * 3);
  // GL wants the bottom row first; readImage the top row first.
  std::vector<uint8_t> texels(size_t(width) * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float a = rgba.at(x, y, 3);
      uint8_t* out = &image_.pixels[(size_t(y) * width + x) * 3];
      uint8_t* tex = &texels[(size_t(height - 1 - y) * width + x) * 4];
      for (int c = 0; c < 3; ++c) {
        const float v = rgba.at(x, y, c) + (1.0f - a) * float(settings.background[c]);
        out[c] = tex[c] = uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
      }
      tex[3] = 255;
    }
  if (!texture_ || texture_.width() != width || texture_.height() != height)
    texture_ = gl::Texture::create2D(GL_RGBA8, width, height);
  texture_.subImage2D(0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  gl::checkGlError("ShearWarpRenderer::render");
  const ShearWarpStats& s = core_.stats();
  stats_ = RenderStats{};
  stats_.slabs = size_t(s.slices);
  stats_.slabsDrawn = stats_.slabs;  // no early stop of the slice loop (rays stop one by one)
  // In the panel's stages: its tables are the classification, slices and warp the compositing.
  stats_.classifyMs = s.tableMs;
  stats_.compositeMs = s.compositeMs + s.warpMs;
  stats_.gpuBytes = size_t(width) * size_t(height) * 4;  // the RGBA8 texture it allocated
  if (s.perspectiveAsParallel)
    stats_.note =
        "shear-warp: this perspective view's intermediate image would be too large (a wide view "
        "from near or inside the volume); drawn as the orthographic view of the "
        "same height at the focal point";
  stats_.renderMs = millisecondsSince(start);
}

}  // namespace ewa
