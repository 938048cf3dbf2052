// WindowInput: GLFW mouse and key callbacks of the viewer window, forwarded to the camera.
#pragma once

#include <string>
#include <vector>

#include "ui/key_bindings.h"

struct GLFWwindow;

namespace ewa {

class CameraController;

class WindowInput {
 public:
  // Installs the callbacks and points the window's user pointer at this object. Create it
  // before the ImGuiLayer, whose callbacks chain to these, and destroy it after.
  WindowInput(GLFWwindow* window, CameraController& controller);
  ~WindowInput();
  WindowInput(const WindowInput&) = delete;
  WindowInput& operator=(const WindowInput&) = delete;

  // ImGui's capture flags from the last frame: presses, scrolls and keys that ImGui wants do
  // not reach the camera (a drag already under way keeps going over the panel).
  void setUiCapture(bool mouse, bool keyboard);
  // Keeps the camera's viewport in step with the window size (cursor coordinates).
  void updateViewportSize();
  // True when any event (input, resize, expose) arrived since the last call: the viewer then
  // draws a few frames so that ImGui can react, and otherwise sleeps in glfwWaitEvents.
  bool takeActivity();
  // Key commands and dropped file paths since the last call, oldest first.
  std::vector<KeyCommand> takeCommands();
  std::vector<std::string> takeDroppedPaths();
  // Where the last double-click on the picture was (window coordinates): CentreOnCursor's point.
  double doubleClickX() const { return doubleClickX_; }
  double doubleClickY() const { return doubleClickY_; }

  // Two left presses at most this far apart in time and space make a double-click.
  static constexpr double kDoubleClickSeconds = 0.35;
  static constexpr double kDoubleClickPixels = 4.0;

 private:
  static WindowInput& from(GLFWwindow* window);
  static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
  static void onCursorPos(GLFWwindow* window, double x, double y);
  static void onScroll(GLFWwindow* window, double dx, double dy);
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void onOtherEvent(GLFWwindow* window);
  static void onDrop(GLFWwindow* window, int count, const char** paths);

  GLFWwindow* window_;
  CameraController& controller_;
  bool uiWantsMouse_ = false;
  bool uiWantsKeyboard_ = false;
  bool activity_ = true;  // draw the first frames
  std::vector<KeyCommand> commands_;
  std::vector<std::string> dropped_;
  double lastLeftPress_ = -1e9;  // glfwGetTime of the last left press on the picture
  double lastLeftX_ = 0.0, lastLeftY_ = 0.0;
  double doubleClickX_ = 0.0, doubleClickY_ = 0.0;
};

}  // namespace ewa
