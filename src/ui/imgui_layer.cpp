// ImGuiLayer: Dear ImGui's context and its GLFW + OpenGL 3 backends for one window.
// This file must not include gl/gl_api.h (see imgui_layer.h).
#include "ui/imgui_layer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdio>
#include <stdexcept>

namespace ewa {

ImGuiLayer::ImGuiLayer(GLFWwindow* window) : window_(window) {
  IMGUI_CHECKVERSION();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini left behind in the working directory
  ImGui::StyleColorsDark();
  try {
    glfwBackend_ = ImGui_ImplGlfw_InitForOpenGL(window, /*install_callbacks=*/true);
    if (!glfwBackend_) throw std::runtime_error("ImGui: GLFW backend failed to start");
    // ImGui_ImplGlfw_Shutdown puts back the callback it replaced, which drops this one too.
    io.UserData = this;
    imguiKeyCallback_ = glfwSetKeyCallback(window, onKey);
    glBackend_ = ImGui_ImplOpenGL3_Init("#version 450");
    if (!glBackend_) throw std::runtime_error("ImGui: OpenGL 3 backend failed to start");
  } catch (...) {
    shutdown();  // the destructor does not run when the constructor throws
    throw;
  }
}

ImGuiLayer::~ImGuiLayer() {
  shutdown();
}

void ImGuiLayer::shutdown() {
  if (!context_) return;
  ImGui::SetCurrentContext(context_);
  if (glBackend_) ImGui_ImplOpenGL3_Shutdown();
  if (glfwBackend_) ImGui_ImplGlfw_Shutdown();  // restores the callbacks it chained to
  ImGui::DestroyContext(context_);
  context_ = nullptr;
  glBackend_ = glfwBackend_ = false;
}

void ImGuiLayer::onKey(GLFWwindow*, int key, int scancode, int action, int mods) {
  auto* self = static_cast<ImGuiLayer*>(ImGui::GetIO().UserData);
  if (!self) return;
  const KeyChange change = action == GLFW_PRESS     ? KeyChange::Press
                           : action == GLFW_RELEASE ? KeyChange::Release
                                                    : KeyChange::Repeat;
  const KeyEvent e{key, scancode, action, mods, change};
  const bool passed = self->keys_.arrive(e);
  if (self->keyLog_) {
    std::printf("key %d %d %s\n", key, action, passed ? "passed" : "held");
    std::fflush(stdout);
  }
  if (passed) self->deliver(e);
}

void ImGuiLayer::deliver(const KeyEvent& e) {
  if (imguiKeyCallback_) imguiKeyCallback_(window_, e.key, e.scancode, e.action, e.mods);
}

void ImGuiLayer::beginFrame() {
  ImGui::SetCurrentContext(context_);
  for (const KeyEvent& e : keys_.beforeNewFrame()) {
    if (keyLog_) std::printf("key %d %d delivered\n", e.key, e.action);
    deliver(e);
  }
  if (keyLog_) std::fflush(stdout);  // the window test waits on these lines
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  keys_.afterNewFrame();
}

void ImGuiLayer::render() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void ImGuiLayer::endFrame() {
  ImGui::EndFrame();
}

bool ImGuiLayer::wantsMouse() const {
  return ImGui::GetIO().WantCaptureMouse;
}

bool ImGuiLayer::wantsKeyboard() const {
  return ImGui::GetIO().WantCaptureKeyboard;
}

void ImGuiLayer::loadLayout(const std::string& iniText) {
  ImGui::SetCurrentContext(context_);
  if (!iniText.empty()) ImGui::LoadIniSettingsFromMemory(iniText.data(), iniText.size());
}

std::string ImGuiLayer::saveLayout() const {
  ImGui::SetCurrentContext(context_);
  size_t size = 0;
  const char* text = ImGui::SaveIniSettingsToMemory(&size);
  return text ? std::string(text, size) : std::string();
}

}  // namespace ewa
