// Queries of the current GL context's size limits.
#include "render/gl_limits.h"

#include <algorithm>
#include <string>

#include "gl/gl_api.h"

namespace ewa {

int maxRenderTargetSize() {
  GLint texture = 0, viewport[2] = {0, 0}, fbWidth = 0, fbHeight = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &fbWidth);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &fbHeight);
  return std::min({texture, viewport[0], viewport[1], fbWidth, fbHeight});
}

bool softwareRasterizer() {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string renderer = name ? name : "";
  return renderer.find("llvmpipe") != std::string::npos ||
         renderer.find("softpipe") != std::string::npos;
}

}  // namespace ewa
