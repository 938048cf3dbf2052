// runViewer: the window's main loop: events, render on change, blit, ImGui panel, swap.
#include "ui/viewer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "core/async_splat_builder.h"
#include "gl/shader_library.h"
#include "platform/glfw_window_context.h"
#include "render/renderer_factory.h"
#include "render/splat_renderer.h"
#include "ui/camera_controller.h"
#include "ui/control_panel.h"
#include "ui/image_presenter.h"
#include "ui/imgui_layer.h"
#include "ui/tf_editor.h"
#include "ui/window_input.h"

namespace ewa {

namespace {

// Frames drawn after the last event before the loop sleeps: ImGui settles hover and click
// states over a couple of frames.
constexpr int kFramesAfterActivity = 3;
// Longest sleep when idle; events wake the loop at once.
constexpr double kIdleWaitSeconds = 0.5;
// Wait while splats are being built on the worker thread: short, so the new set shows soon.
constexpr double kBuildPollSeconds = 0.02;

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Everything that lives as long as the window; members are destroyed in reverse order, so GL
// objects go before the context and ImGui before the callbacks it chains to.
class Viewer {
 public:
  Viewer(platform::GlfwWindowContext& window, const Volume& volume, const TransferFunction& tf,
         const ViewerConfig& config)
      : window_(window),
        shaders_(config.shaderDir),
        volume_(volume),
        tf_(tf),
        controller_(config.camera),
        settings_(config.settings),
        input_(window.window(), controller_),
        imgui_(window.window()),
        panel_(config.volumeName, volume),
        tfEditor_(volume, tf, "transfer_function.json") {
    const char* printLayout = std::getenv("EWAVIEW_PRINT_LAYOUT");
    tfEditor_.setPrintLayout(printLayout && *printLayout == '1');
    makeRenderer();
  }

  void run() {
    int quietFrames = 0;
    while (!window_.shouldClose()) {
      if (quietFrames >= kFramesAfterActivity) {
        glfwWaitEventsTimeout(splatBuilder_.busy() ? kBuildPollSeconds : kIdleWaitSeconds);
      } else {
        glfwPollEvents();
      }
      const Clock::time_point start = Clock::now();
      // `|`, not `||`: both must run (take the flag and swap in a finished splat set).
      const bool active = input_.takeActivity() | takeBuiltSplats();
      if (!active && quietFrames >= kFramesAfterActivity) continue;  // nothing to redraw

      const bool rendered = drawFrame();
      frameStats_.frameMs = millisecondsSince(start);
      // A new image changes the statistics shown, so draw at least one more frame.
      quietFrames = (active || rendered) ? 0 : quietFrames + 1;
    }
  }

 private:
  // Swaps in a splat set the worker finished; true when one arrived.
  bool takeBuiltSplats() {
    try {
      std::optional<BuiltSplats> built = splatBuilder_.poll();
      if (!built) return false;
      // A set finished after a switch to another renderer is of no use.
      if (auto* splat = dynamic_cast<SplatRenderer*>(renderer_.get())) {
        splat->setSplats(std::move(built->splats), built->classification);
        ++tfRevision_;
      }
    } catch (const std::exception& e) {  // too many visible voxels: say so, keep the old set
      renderError_ = e.what();
      std::cerr << "ewaview: " << renderError_ << " (the window keeps running)\n";
    }
    return true;
  }

  // The renderer settings_.renderer names, given the volume and transfer function.
  void makeRenderer() {
    renderer_ = createRenderer(settings_.renderer, shaders_);
    rendererKind_ = settings_.renderer;
    renderer_->setVolume(volume_);
    renderer_->setTransferFunction(tf_);
  }

  // One frame; returns true when the volume was rendered again.
  bool drawFrame() {
    input_.updateViewportSize();
    const glm::ivec2 fb = window_.framebufferSize();
    if (fb.x <= 0 || fb.y <= 0) return false;  // minimised

    imgui_.beginFrame();
    Camera camera = controller_.camera();
    const PanelEdits edits = panel_.draw(settings_, camera, frameStats_);
    if (edits.camera) controller_.setCamera(camera);
    if (edits.resetCamera) controller_.reset();
    if (edits.settings) ++settingsRevision_;
    if (tfEditor_.draw()) {
      tf_ = tfEditor_.transferFunction();
      if (auto* splat = dynamic_cast<SplatRenderer*>(renderer_.get())) {
        // The new table is on the GPU for this frame; the old splats draw with it until the
        // worker's set for the new function is swapped in.
        splat->updateTransferTexture(tf_);
        splatBuilder_.request(volume_, tf_, settings_.classification, splat->maxSplats());
      } else {
        renderer_->setTransferFunction(tf_);
      }
      ++tfRevision_;
    }
    if (settings_.renderer != rendererKind_) makeRenderer();

    const bool stale = !hasImage_ || renderedCamera_ != controller_.revision() ||
                       renderedSettings_ != settingsRevision_ || renderedSize_ != fb ||
                       renderedTf_ != tfRevision_;
    if (stale) {
      renderSafely(fb);
      hasImage_ = true;
      renderedCamera_ = controller_.revision();
      renderedSettings_ = settingsRevision_;
      renderedSize_ = fb;
      renderedTf_ = tfRevision_;
      frameStats_.render = renderer_->stats();
      frameStats_.imageWidth = fb.x;
      frameStats_.imageHeight = fb.y;
    }

    presenter_.present(renderer_->outputTexture(), renderedSize_.x, renderedSize_.y, fb.x, fb.y);
    if (!renderError_.empty()) {
      ImGui::GetForegroundDrawList()->AddText(ImVec2(10.0f, float(fb.y) - 30.0f),
                                              IM_COL32(255, 90, 90, 255), renderError_.c_str());
    }
    imgui_.render();
    window_.swapBuffers();
    // ImGui decides what it captures while building the frame; the next events obey that.
    input_.setUiCapture(imgui_.wantsMouse(), imgui_.wantsKeyboard());
    return stale;
  }

  // A GL failure while rendering (out of memory, a limit, an incomplete framebuffer) keeps the
  // window open: the message is printed once and shown until a change renders again.
  void renderSafely(glm::ivec2 fb) {
    try {
      renderer_->render(controller_.camera(), settings_, fb.x, fb.y);
      renderError_.clear();
    } catch (const std::exception& e) {
      std::string message = e.what();
      for (char& c : message) c = (c == '\n' || c == '\r') ? ' ' : c;
      if (message != renderError_)
        std::cerr << "ewaview: " << message << " (the window keeps running)\n";
      renderError_ = message;
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
  }

  platform::GlfwWindowContext& window_;
  gl::ShaderLibrary shaders_;
  const Volume& volume_;
  TransferFunction tf_;
  std::unique_ptr<Renderer> renderer_;
  RendererKind rendererKind_ = RendererKind::Splat;
  ImagePresenter presenter_;
  CameraController controller_;
  RenderSettings settings_;
  WindowInput input_;
  ImGuiLayer imgui_;
  ControlPanel panel_;
  TfEditor tfEditor_;
  AsyncSplatBuilder splatBuilder_;  // after the renderer: destroyed first, joining its worker

  FrameStats frameStats_;
  uint64_t settingsRevision_ = 0;
  bool hasImage_ = false;
  uint64_t renderedCamera_ = 0;
  uint64_t renderedSettings_ = 0;
  glm::ivec2 renderedSize_{0, 0};
  uint64_t tfRevision_ = 0;
  uint64_t renderedTf_ = 0;
  std::string renderError_;
};

}  // namespace

int runViewer(const Volume& volume, const TransferFunction& tf, const ViewerConfig& config) {
  std::unique_ptr<platform::GlfwWindowContext> window;
  try {
    platform::WindowOptions options;
    options.width = config.width;
    options.height = config.height;
    options.title = config.title;
    window = std::make_unique<platform::GlfwWindowContext>(options);
  } catch (const platform::ContextError& e) {
    std::cerr << "ewaview: " << e.what() << "\n";
    return 1;
  }
  Viewer viewer(*window, volume, tf, config);
  viewer.run();
  return 0;
}

}  // namespace ewa
