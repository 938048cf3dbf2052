// GlfwWindowContext: an on-screen window with an OpenGL 4.5 core context, for the interactive UI.
#pragma once

#include <glm/vec2.hpp>
#include <memory>
#include <string>

#include "platform/gl_context.h"
#include "platform/glfw_library.h"

struct GLFWwindow;  // <GLFW/glfw3.h> stays out of this header

namespace ewa::platform {

struct WindowOptions {
  int width = 1280;
  int height = 800;
  std::string title = "ewaview";
  bool visible = true;
  bool vsync = true;
};

class GlfwWindowContext final : public GlContext {
 public:
  // Opens a window with a forward-compatible OpenGL 4.5 core context and leaves it current.
  // `glfw` is the shared GLFW initialisation; when null the window makes its own (fine for a
  // single window). Throws ContextError when GLFW or the window/context cannot be created.
  explicit GlfwWindowContext(const WindowOptions& options = {},
                             std::shared_ptr<GlfwLibrary> glfw = nullptr);
  ~GlfwWindowContext() override;

  void* getProcAddress(const char* name) override;
  // A hidden 1x1 window's context sharing this one's objects.
  std::unique_ptr<UploadContext> createUploadContext() override;

  // For the UI (ImGui's GLFW backend, input callbacks).
  GLFWwindow* window() const { return window_; }
  void swapBuffers();
  bool shouldClose() const;
  // In pixels, which differs from the window size on high-DPI screens.
  glm::ivec2 framebufferSize() const;
  const std::shared_ptr<GlfwLibrary>& glfw() const { return glfw_; }

 protected:
  void makeNativeCurrent() override;

 private:
  void destroy();

  std::shared_ptr<GlfwLibrary> glfw_;  // declared first: outlives the window
  GLFWwindow* window_ = nullptr;
};

}  // namespace ewa::platform
