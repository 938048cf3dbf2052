// GlfwLibrary: GLFW initialisation and termination, and GLFW's last error text.
#include "platform/glfw_library.h"

#include <GLFW/glfw3.h>

#include <string>

#include "platform/gl_context.h"

namespace ewa::platform {

const char* glfwLastError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown error";
}

GlfwLibrary::GlfwLibrary() {
  if (!glfwInit())
    throw ContextError(std::string("GLFW: initialisation failed: ") + glfwLastError());
}

GlfwLibrary::~GlfwLibrary() {
  glfwTerminate();
}

}  // namespace ewa::platform
