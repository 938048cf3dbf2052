// GlfwWindowContext: GLFW window and 4.5 core context creation, buffer swaps and sizes.
#include "platform/glfw_window_context.h"

#include <GLFW/glfw3.h>

#include <utility>

namespace ewa::platform {

namespace {

void coreContextHints() {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
}

// A hidden window's context; destroyed on the thread that made it (GLFW's rule for windows).
class GlfwUploadContext final : public UploadContext {
 public:
  explicit GlfwUploadContext(GLFWwindow* window) : window_(window) {}
  ~GlfwUploadContext() override { glfwDestroyWindow(window_); }
  void bindNative() override {
    glfwMakeContextCurrent(window_);
    if (glfwGetCurrentContext() != window_)
      throw ContextError(std::string("GLFW: cannot bind the upload context: ") + glfwLastError());
  }
  void releaseNative() override { glfwMakeContextCurrent(nullptr); }

 private:
  GLFWwindow* window_;
};

}  // namespace

GlfwWindowContext::GlfwWindowContext(const WindowOptions& options,
                                     std::shared_ptr<GlfwLibrary> glfw)
    : GlContext("GLFW"), glfw_(glfw ? std::move(glfw) : GlfwLibrary::create()) {
  coreContextHints();
  glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
  window_ =
      glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (!window_) {
    throw ContextError(std::string("GLFW: cannot open a window with OpenGL 4.5 core: ") +
                       glfwLastError());
  }
  try {
    initializeGl();
  } catch (...) {
    destroy();  // the destructor does not run when the constructor throws
    throw;
  }
  glfwSwapInterval(options.vsync ? 1 : 0);
}

GlfwWindowContext::~GlfwWindowContext() {
  destroy();
}

void GlfwWindowContext::makeNativeCurrent() {
  glfwMakeContextCurrent(window_);
}

void* GlfwWindowContext::getProcAddress(const char* name) {
  return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

std::unique_ptr<UploadContext> GlfwWindowContext::createUploadContext() {
  coreContextHints();
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  GLFWwindow* hidden = glfwCreateWindow(1, 1, "ewaview uploads", nullptr, window_);
  if (!hidden) return nullptr;
  return std::make_unique<GlfwUploadContext>(hidden);
}

void GlfwWindowContext::swapBuffers() {
  glfwSwapBuffers(window_);
}

bool GlfwWindowContext::shouldClose() const {
  return glfwWindowShouldClose(window_) != 0;
}

glm::ivec2 GlfwWindowContext::framebufferSize() const {
  glm::ivec2 size(0, 0);
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

void GlfwWindowContext::destroy() {
  if (!window_) return;
  if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
  glfwDestroyWindow(window_);
  window_ = nullptr;
}

}  // namespace ewa::platform
