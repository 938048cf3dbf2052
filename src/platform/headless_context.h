// Headless context factory: picks OSMesa or EGL by name for off-screen rendering and tests.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "platform/gl_context.h"

namespace ewa::platform {

enum class HeadlessBackend { OsMesa, Egl };

// Creates a current OpenGL 4.5 core context of `backend`. width x height is the size of its
// default framebuffer (unused by EGL's surfaceless contexts); rendering is meant for FBOs.
// Throws ContextError when the backend cannot provide one.
std::unique_ptr<GlContext> createHeadlessContext(HeadlessBackend backend, int width = 16,
                                                 int height = 16);

// "osmesa" or "egl" (any case); throws std::invalid_argument naming the bad value otherwise.
HeadlessBackend parseHeadlessBackend(const std::string& name);
// "osmesa" or "egl".
const char* headlessBackendName(HeadlessBackend backend);
// Every backend's name, the default first (the --backend option's values).
std::vector<std::string> headlessBackendNames();
// The backend programs use when none is named: EWAVIEW_BACKEND's ("osmesa" or "egl", say on a
// GPU server), else "osmesa". Throws std::invalid_argument naming the variable for another value.
std::string defaultHeadlessBackend();

}  // namespace ewa::platform
