// GlfwLibrary: owns GLFW's initialisation (glfwInit in the constructor, glfwTerminate at the end).
#pragma once

#include <memory>

namespace ewa::platform {

// GLFW's state is process-wide and glfwTerminate destroys every window, so all windows should
// share one GlfwLibrary (GlfwWindowContext holds a shared_ptr to it) instead of each owning one.
class GlfwLibrary {
 public:
  // Throws ContextError "GLFW: initialisation failed: <reason>" (e.g. no display).
  GlfwLibrary();
  ~GlfwLibrary();
  GlfwLibrary(const GlfwLibrary&) = delete;
  GlfwLibrary& operator=(const GlfwLibrary&) = delete;

  static std::shared_ptr<GlfwLibrary> create() { return std::make_shared<GlfwLibrary>(); }
};

// GLFW's last error description for this thread, or "unknown error"; clears it.
const char* glfwLastError();

}  // namespace ewa::platform
