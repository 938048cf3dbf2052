// GPU memory figures the driver reports (GL_NVX_gpu_memory_info), when it reports any.
#pragma once

#include <cstdint>
#include <optional>

namespace ewa::gl {

struct GpuMemoryInfo {
  int64_t totalKiB = 0;      // dedicated video memory
  int64_t availableKiB = 0;  // currently free
};

// True when the current context lists the extension `name`.
bool hasExtension(const char* name);
// The NVIDIA query when GL_NVX_gpu_memory_info is present (a current context is needed);
// nothing on Mesa and other drivers.
std::optional<GpuMemoryInfo> queryGpuMemory();

}  // namespace ewa::gl
