// GPU memory figures through GL_NVX_gpu_memory_info.
#include "gl/gpu_memory.h"

#include <cstring>

#include "gl/gl_api.h"

namespace ewa::gl {

namespace {
// From the GL_NVX_gpu_memory_info specification (not in the core headers the loader uses).
constexpr GLenum kDedicatedVidmemNvx = 0x9047;
constexpr GLenum kCurrentAvailableVidmemNvx = 0x9049;
}  // namespace

bool hasExtension(const char* name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* ext = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
    if (ext && std::strcmp(ext, name) == 0) return true;
  }
  return false;
}

std::optional<GpuMemoryInfo> queryGpuMemory() {
  if (!hasExtension("GL_NVX_gpu_memory_info")) return std::nullopt;
  GLint total = 0, available = 0;
  glGetIntegerv(kDedicatedVidmemNvx, &total);
  glGetIntegerv(kCurrentAvailableVidmemNvx, &available);
  glGetError();  // a driver that lists the extension but rejects the enums leaves an error
  return GpuMemoryInfo{total, available};
}

}  // namespace ewa::gl
