// ImGuiLayer: Dear ImGui's context and its GLFW + OpenGL 3 backends for one window.
#pragma once

#include <string>

#include "ui/key_trickle.h"

struct GLFWwindow;
struct ImGuiContext;

namespace ewa {

// Kept apart from the project's GL code: ImGui's OpenGL backend brings its own GL loader, whose
// glFoo names clash with gl/gl_api.h, so only imgui_layer.cpp includes the backends.
class ImGuiLayer {
 public:
  // The window's GL context must be current. ImGui's GLFW callbacks chain to the ones already
  // installed on `window`, so install the application's callbacks first. Throws
  // std::runtime_error when a backend cannot start.
  explicit ImGuiLayer(GLFWwindow* window);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // Starts a frame: ImGui widget calls may follow until render(). Key events held back since
  // the last frame (KeyTrickle) are delivered first.
  void beginFrame();
  // Ends the frame and draws the widgets over the current framebuffer (GL state is restored).
  void render();
  // Ends the frame without drawing it (a frame that is not presented).
  void endFrame();

  // Whether ImGui used the mouse / keyboard in the last frame (the cursor is over a window, a
  // widget is being dragged, a text field has focus): the camera must then leave them alone.
  bool wantsMouse() const;
  bool wantsKeyboard() const;

  // Key events held for a later frame (KeyTrickle): the window must keep drawing frames until
  // none is left, or they would wait for the next input.
  bool keysHeld() const { return keys_.heldCount() > 0; }
  // Logs every key event to stdout as it arrives ("key K A passed|held") and as a held one is
  // delivered ("key K A delivered"): the scripted window test's record of what GLFW gave.
  void setKeyLog(bool on) { keyLog_ = on; }

  // Panel layout (ImGui's ini text): ImGui never writes a file itself; the viewer keeps the
  // text in its config folder, written atomically. Load before the first frame.
  void loadLayout(const std::string& iniText);
  std::string saveLayout() const;

 private:
  void shutdown();
  // On top of ImGui's key callback: passes each event on to it (and through it to the
  // application's) unless KeyTrickle holds it for the next frame.
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  void deliver(const KeyEvent& e);

  GLFWwindow* window_ = nullptr;
  ImGuiContext* context_ = nullptr;
  void (*imguiKeyCallback_)(GLFWwindow*, int, int, int, int) = nullptr;
  KeyTrickle keys_;
  bool keyLog_ = false;
  bool glfwBackend_ = false;
  bool glBackend_ = false;
};

}  // namespace ewa
