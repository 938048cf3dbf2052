// WindowInput: GLFW mouse and key callbacks of the viewer window, forwarded to the camera.
#include "ui/window_input.h"

#include <GLFW/glfw3.h>

#include <cmath>
#include <utility>

#include "core/camera_controller.h"

namespace ewa {

WindowInput::WindowInput(GLFWwindow* window, CameraController& controller)
    : window_(window), controller_(controller) {
  glfwSetWindowUserPointer(window_, this);
  glfwSetMouseButtonCallback(window_, onMouseButton);
  glfwSetCursorPosCallback(window_, onCursorPos);
  glfwSetScrollCallback(window_, onScroll);
  glfwSetKeyCallback(window_, onKey);
  glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned) { onOtherEvent(w); });
  glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int) { onOtherEvent(w); });
  glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int) { onOtherEvent(w); });
  glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { onOtherEvent(w); });
  glfwSetWindowRefreshCallback(window_, onOtherEvent);
  glfwSetDropCallback(window_, onDrop);
  updateViewportSize();
}

WindowInput::~WindowInput() {
  glfwSetMouseButtonCallback(window_, nullptr);
  glfwSetCursorPosCallback(window_, nullptr);
  glfwSetScrollCallback(window_, nullptr);
  glfwSetKeyCallback(window_, nullptr);
  glfwSetCharCallback(window_, nullptr);
  glfwSetCursorEnterCallback(window_, nullptr);
  glfwSetWindowFocusCallback(window_, nullptr);
  glfwSetFramebufferSizeCallback(window_, nullptr);
  glfwSetWindowRefreshCallback(window_, nullptr);
  glfwSetDropCallback(window_, nullptr);
  glfwSetWindowUserPointer(window_, nullptr);
}

void WindowInput::setUiCapture(bool mouse, bool keyboard) {
  uiWantsMouse_ = mouse;
  uiWantsKeyboard_ = keyboard;
}

void WindowInput::updateViewportSize() {
  int width = 0, height = 0;
  glfwGetWindowSize(window_, &width, &height);
  controller_.setViewportSize(width, height);
}

bool WindowInput::takeActivity() {
  const bool any = activity_;
  activity_ = false;
  return any;
}

std::vector<KeyCommand> WindowInput::takeCommands() {
  return std::exchange(commands_, {});
}

std::vector<std::string> WindowInput::takeDroppedPaths() {
  return std::exchange(dropped_, {});
}

void WindowInput::onDrop(GLFWwindow* window, int count, const char** paths) {
  WindowInput& self = from(window);
  self.activity_ = true;
  for (int n = 0; n < count; ++n) self.dropped_.emplace_back(paths[n]);
}

WindowInput& WindowInput::from(GLFWwindow* window) {
  return *static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
}

void WindowInput::onMouseButton(GLFWwindow* window, int button, int action, int mods) {
  WindowInput& self = from(window);
  self.activity_ = true;
  MouseButton which;
  switch (button) {
    case GLFW_MOUSE_BUTTON_LEFT:
      which = MouseButton::Left;
      break;
    case GLFW_MOUSE_BUTTON_MIDDLE:
      which = MouseButton::Middle;
      break;
    case GLFW_MOUSE_BUTTON_RIGHT:
      which = MouseButton::Right;
      break;
    default:
      return;
  }
  if (action == GLFW_RELEASE) {
    self.controller_.releaseButton(which);  // always, so a drag never sticks
    return;
  }
  if (action != GLFW_PRESS || self.uiWantsMouse_) return;
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  if (which == MouseButton::Left && !(mods & GLFW_MOD_SHIFT)) {
    const double t = glfwGetTime();
    if (t - self.lastLeftPress_ <= kDoubleClickSeconds &&
        std::hypot(x - self.lastLeftX_, y - self.lastLeftY_) <= kDoubleClickPixels) {
      self.commands_.push_back(KeyCommand::CentreOnCursor);
      self.doubleClickX_ = x;
      self.doubleClickY_ = y;
      self.lastLeftPress_ = -1e9;  // a third click starts a new pair
    } else {
      self.lastLeftPress_ = t;
      self.lastLeftX_ = x;
      self.lastLeftY_ = y;
    }
  }
  self.controller_.pressButton(which, (mods & GLFW_MOD_SHIFT) != 0, x, y);
}

void WindowInput::onCursorPos(GLFWwindow* window, double x, double y) {
  WindowInput& self = from(window);
  self.activity_ = true;  // ImGui's hover highlights follow the cursor too
  self.controller_.moveCursor(x, y);
}

void WindowInput::onScroll(GLFWwindow* window, double dx, double dy) {
  WindowInput& self = from(window);
  self.activity_ = true;
  if (!self.uiWantsMouse_) self.controller_.scroll(dy);
}

void WindowInput::onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
  WindowInput& self = from(window);
  self.activity_ = true;
  if (action != GLFW_PRESS || self.uiWantsKeyboard_) return;
  const KeyBinding* binding = keyBindingFor(key, mods);  // the key table, key_bindings.cpp
  if (!binding) return;
  switch (binding->command) {
    case KeyCommand::ResetCamera:
      self.controller_.reset();
      break;
    case KeyCommand::Quit:
      glfwSetWindowShouldClose(window, GLFW_TRUE);
      break;
    default:
      self.commands_.push_back(binding->command);
  }
}

void WindowInput::onOtherEvent(GLFWwindow* window) {
  from(window).activity_ = true;
}

}  // namespace ewa
