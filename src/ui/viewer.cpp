// runViewer: the window's main loop: events, level-of-detail rendering, panels, swap.
#include "ui/viewer.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "core/camera_path.h"
#include "core/camera_views.h"
#include "core/lod_policy.h"
#include "gl/gpu_memory.h"
#include "gl/shader_library.h"
#include "io/atomic_file.h"
#include "io/frame_names.h"
#include "io/frame_sink.h"
#include "io/png_io.h"
#include "io/terminal_progress.h"
#include "platform/glfw_window_context.h"
#include "render/lod_renderer.h"
#include "render/renderer_factory.h"
#include "ui/camera_controller.h"
#include "ui/control_panel.h"
#include "ui/file_dialog.h"
#include "ui/image_presenter.h"
#include "ui/imgui_layer.h"
#include "ui/bookmark_store.h"
#include "ui/session_panel.h"
#include "ui/status_messages.h"
#include "ui/live_transfer_function.h"
#include "ui/window_input.h"

namespace ewa {

namespace {

// Frames drawn after the last event before the loop sleeps: ImGui settles hover and click
// states over a couple of frames.
constexpr int kFramesAfterActivity = 3;
// Longest sleep when idle; events wake the loop at once.
constexpr double kIdleWaitSeconds = 0.5;
// Redraw rate while a volume loads (the progress bar moves).
constexpr double kLoadingWaitSeconds = 0.1;
// Wait while splats are built on the worker thread: short, so the new set shows soon.
constexpr double kBuildPollSeconds = 0.02;

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A turntable being written from the window, one frame per loop iteration.
struct WindowTurntable {
  int total = 0;  // 0: none running
  int done = 0;
  Camera start;
  std::unique_ptr<FrameSink> sink;  // PNG frames in a folder, or a video
  std::unique_ptr<TerminalProgress> progress;
};

// Everything that lives as long as the window; members are destroyed in reverse order, so GL
// objects go before the context and ImGui before the callbacks it chains to.
class Viewer {
 public:
  Viewer(platform::GlfwWindowContext& window, LoadedVolume initial, const ViewerConfig& config)
      : window_(window),
        config_(config),
        saved_(config.saved),
        shaders_(config.shaderDir),
        lod_([this] { return createRenderer(settings_.renderer, shaders_); }),
        controller_(config.camera),
        settings_(config.settings),
        input_(window.window(), controller_),
        imgui_(window.window()),
        panel_(initial.name, *initial.volume) {
    if (!config_.configDir.empty()) {
      try {
        imgui_.loadLayout(readTextFile(imguiIniPathIn(config_.configDir)));
      } catch (const std::exception&) {
        // No layout saved yet: ImGui's defaults.
      }
    }
    rendererKind_ = settings_.renderer;  // lod_ makes renderers of this kind
    const char* printLayout = std::getenv("EWAVIEW_PRINT_LAYOUT");
    printLayout_ = printLayout && *printLayout == '1';
    levelOfDetail_ = saved_.levelOfDetail;
    hasNvx_ = gl::queryGpuMemory().has_value();
    if (initial.coarse.levels.empty()) initial.coarse = buildLodVolumes(*initial.volume);
    adopt(std::move(initial), /*newCamera=*/false);
    lod_.prepareFullLevel();  // shader failures throw here: one line, exit 1
  }

  void run() {
    int quietFrames = 0;
    while (!window_.shouldClose()) {
      const double wait = quietFrames < kFramesAfterActivity ? 0.0 : waitSeconds();
      if (wait > 0.0)
        glfwWaitEventsTimeout(wait);
      else
        glfwPollEvents();
      const Clock::time_point start = Clock::now();
      // `|`, not `||`: both must run (take the flag and swap in a finished splat set).
      const bool active = input_.takeActivity() | takeBuiltSplats();
      const bool due = busy() || refineDue() || !messages_.current(now()).empty();
      if (!active && !due && quietFrames >= kFramesAfterActivity) continue;

      const bool rendered = drawFrame();
      frameStats_.frameMs = millisecondsSince(start);
      // A new image changes the statistics shown, so draw at least one more frame.
      quietFrames = (active || rendered) ? 0 : quietFrames + 1;
    }
  }

  // The cameras of the moving frames, replayable by ewaview-interact-bench --path.
  void saveRecording() {
    if (config_.recordCameraPath.empty()) return;
    try {
      writeFileAtomically(config_.recordCameraPath,
                          "# ewaview camera path recorded from the window (" + current_.name +
                              "), one line per moving frame\n" + recorded_);
      std::cerr << "ewaview: camera path written to " << config_.recordCameraPath << "\n";
    } catch (const std::exception& e) {
      std::cerr << "ewaview: " << e.what() << "\n";
    }
  }

  // Window size, render settings, recent files and the panel layout, for the next run.
  void saveSettings() {
    if (config_.configDir.empty()) return;
    int w = 0, h = 0;
    glfwGetWindowSize(window_.window(), &w, &h);
    if (w > 0 && h > 0) {
      saved_.windowWidth = w;
      saved_.windowHeight = h;
    }
    saved_.filter = settings_.filter;
    saved_.renderMode = renderModeName(settings_.mode);
    saved_.cutoff = settings_.cutoff;
    saved_.slabThickness = settings_.slabThickness;
    saved_.background = settings_.background;
    saved_.levelOfDetail = levelOfDetail_;
    std::string problem;
    saved_.lastTransferFunction =
        liveTf_.keep(config_.configDir, saved_.lastTransferFunction, &problem);
    if (!problem.empty()) std::cerr << "ewaview: " << problem << "\n";
    try {
      saveViewerSettings(settingsPathIn(config_.configDir), saved_);
      writeFileAtomically(imguiIniPathIn(config_.configDir), imgui_.saveLayout(), true);
    } catch (const std::exception& e) {
      std::cerr << "ewaview: " << e.what() << "\n";
    }
  }

 private:
  double now() const { return std::chrono::duration<double>(Clock::now() - epoch_).count(); }
  bool busy() const {
    return loadJob_.running() || turntable_.total > 0 || buildPending_ || liveTf_.building();
  }
  // A coarse image is shown and the quiet time before full quality has passed.
  bool refineDue() const {
    return hasImage_ && lod_.lastLevel() != 0 &&
           policy_.shouldRefine(millisecondsSince(lastChange_));
  }
  double waitSeconds() const {
    if (turntable_.total > 0 || buildPending_) return 0.0;
    if (liveTf_.building()) return kBuildPollSeconds;
    if (hasImage_ && lod_.lastLevel() != 0)
      return std::max(0.0, (policy_.refineDelayMs() - millisecondsSince(lastChange_)) / 1000.0);
    if (loadJob_.running()) return kLoadingWaitSeconds;
    return kIdleWaitSeconds;
  }

  void info(const std::string& text) {
    messages_.post(StatusMessages::Kind::Info, text, now());
    std::cerr << "ewaview: " << text << "\n";
  }
  void error(const std::string& text) {
    messages_.post(StatusMessages::Kind::Error, text, now());
    std::cerr << "ewaview: " << text << "\n";
  }

  // Makes `loaded` the volume on screen (the old one stays alive until the renderers let go).
  void adopt(LoadedVolume loaded, bool newCamera) {
    liveTf_.dropBuild();  // a build may still read the old volume
    LoadedVolume old = std::move(current_);
    current_ = std::move(loaded);
    lod_.setVolume(*current_.volume, current_.coarse);
    lod_.setTransferFunction(current_.tf);
    policy_.resetMeasurements();
    panel_.setVolume(current_.name, *current_.volume);
    liveTf_.reset(*current_.volume, current_.tf,
                  saved_.lastTransferFunction.empty() ? "transfer_function.json"
                                                      : saved_.lastTransferFunction,
                  printLayout_);
    if (newCamera) {
      const glm::ivec2 fb = window_.framebufferSize();
      Camera camera;
      camera.viewAngleDeg = controller_.camera().viewAngleDeg;
      camera.orthographic = controller_.camera().orthographic;
      camera = initialVolumeView(camera, current_.volume->worldBoundsMin(),
                                 current_.volume->worldBoundsMax(),
                                 fb.y > 0 ? double(fb.x) / fb.y : 1.0, current_.volume->patientFrame());
      controller_.restart(camera);
    }
    if (!current_.path.empty()) addRecentFile(saved_.recentFiles, current_.path);
    const std::string problem = bookmarks_.open(current_.path, current_.name, config_.configDir);
    if (!problem.empty()) error(problem);
    hasImage_ = false;
    buildPending_ = true;  // one frame says so before the first (slow) render classifies
  }

  void startLoad(const std::string& path) {
    if (loadJob_.running()) {
      error("still loading " + loadJob_.path() + "; try again when it is done");
      return;
    }
    std::cerr << "ewaview: loading " << path << "\n";
    loadJob_.start(path, config_.opener);
  }

  void pollLoad() {
    std::optional<LoadedVolume> loaded;
    std::string problem;
    const double seconds = loadJob_.elapsedSeconds();
    if (!loadJob_.poll(&loaded, &problem)) return;
    if (!loaded) {
      error(problem);  // the old volume stays
      return;
    }
    char text[64];
    std::snprintf(text, sizeof text, " in %.1f s", seconds);
    info("opened " + loaded->name + text);
    // Uneven slices, a sheared grid: on stderr already (loadScene), and in the panel.
    for (const std::string& note : loaded->volume->notes())
      if (note.rfind("warning: ", 0) == 0) messages_.post(StatusMessages::Kind::Info, note, now());
    adopt(std::move(*loaded), /*newCamera=*/true);
  }



  // Every level's renderer is of the kind settings_.renderer names (the panel switches it).
  LodRenderer::Factory rendererFactory() {
    rendererKind_ = settings_.renderer;
    return [this] { return createRenderer(settings_.renderer, shaders_); };
  }

  // A new set of renderers when the panel switched the renderer kind.
  void switchRendererIfAsked() {
    if (settings_.renderer == rendererKind_) return;
    liveTf_.dropBuild();
    lod_ = LodRenderer(rendererFactory());
    lod_.setVolume(*current_.volume, current_.coarse);
    lod_.setTransferFunction(current_.tf);
    policy_.resetMeasurements();
    hasImage_ = false;
  }

  // Renders LodPolicy level `level` of the current view; returns the milliseconds it took.
  // A GL failure (out of memory, a limit, an incomplete framebuffer) keeps the window open:
  // the message is shown in the window and printed once, until a change renders again.
  double renderLevel(int level, const Camera& camera, const glm::ivec2& fb) {
    const Clock::time_point start = Clock::now();
    try {
      lod_.render(level, camera, settings_, fb.x, fb.y);
      renderError_.clear();
    } catch (const std::exception& e) {
      std::string message = e.what();
      for (char& c : message) c = (c == '\n' || c == '\r') ? ' ' : c;
      if (message != renderError_) error(message + " (the window keeps running)");
      renderError_ = message;
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      hasImage_ = true;  // retried when the view, settings or size change, not every frame
      renderedCamera_ = controller_.revision();
      renderedSettings_ = settingsRevision_;
      renderedSize_ = fb;
      renderedTf_ = liveTf_.revision();
      return millisecondsSince(start);
    }
    const double ms = millisecondsSince(start);
    hasImage_ = true;
    renderedCamera_ = controller_.revision();
    renderedSettings_ = settingsRevision_;
    renderedSize_ = fb;
    renderedTf_ = liveTf_.revision();
    frameStats_.render = lod_.last().stats();
    frameStats_.imageWidth = lod_.imageWidth();
    frameStats_.imageHeight = lod_.imageHeight();
    frameStats_.lodLevel = level;
    frameStats_.gpuBytes = lod_.gpuBytes();
    if (hasNvx_) frameStats_.gpuMemory = gl::queryGpuMemory();
    return ms;
  }





  // Swaps in a splat set the worker finished; true when one arrived. Full quality on screen
  // is drawn again at once; a coarse picture refines later anyway.
  bool takeBuiltSplats() {
    std::string problem;
    if (!liveTf_.takeBuilt(lod_, &problem)) return false;
    if (!problem.empty())
      error(problem + " (the window keeps running)");
    else
      fullSplatsArrived_ = hasImage_ && lod_.lastLevel() == 0;
    return true;
  }

  void saveBookmarks() {
    std::string note;
    const std::string problem = bookmarks_.save(&note);
    if (!problem.empty()) error(problem);
    if (!note.empty()) info(note);
  }

  void screenshot(const glm::ivec2& fb) {
    try {
      // Always the full-quality picture, even if a coarse one is on screen.
      if (!hasImage_ || lod_.lastLevel() != 0) renderLevel(0, controller_.camera(), fb);
      const std::string path =
          std::filesystem::absolute(
              screenshotFileName(saved_.screenshotDir, current_.name, std::time(nullptr)))
              .lexically_normal()
              .string();
      writePng(path, lod_.last().readImage());
      info("saved screenshot " + path);
    } catch (const std::exception& e) {
      error(e.what());
    }
  }

  // `format`: "png" (a folder of frames), "mp4" or "webm" (a video at `fps`).
  void startTurntable(int frames, const std::string& format, int fps) {
    std::string folder =
        std::filesystem::absolute(
            screenshotFileName(saved_.screenshotDir, current_.name, std::time(nullptr)))
            .lexically_normal()
            .string();
    folder = folder.substr(0, folder.size() - 4) + "-turntable";
    try {
      turntable_.sink = openFrameSink(format == "png" ? folder : folder + "." + format, frames, fps);
    } catch (const std::exception& e) {
      error(e.what());
      return;
    }
    turntable_.total = frames;
    turntable_.done = 0;
    turntable_.start = controller_.camera();
    turntable_.progress = std::make_unique<TerminalProgress>("ewaview: turntable");
  }

  // One turntable frame; ends the turntable after the last one.
  void turntableFrame(const glm::ivec2& fb) {
    WindowTurntable& t = turntable_;
    const std::string file = t.sink->fileOf(t.done);
    try {
      renderLevel(0, turntableCamera(t.start, t.done, t.total), fb);
      renderedCamera_ = ~uint64_t(0);  // the view on screen is not the controller's camera
      t.sink->add(lod_.last().readImage(), t.done);
      if (t.done + 1 == t.total) t.sink->finish();
    } catch (const std::exception& e) {
      error(e.what());
      t = WindowTurntable{};
      return;
    }
    ++t.done;
    t.progress->update(t.done, t.total, file);
    if (t.done == t.total) {
      t.progress->finish("done");
      messages_.post(StatusMessages::Kind::Info,
                     "saved " + std::to_string(t.total) + " frames in " + t.sink->description(),
                     now());
      t = WindowTurntable{};
    }
  }

  void applyCommands(const glm::ivec2& fb, bool* screenshotNow) {
    for (KeyCommand c : input_.takeCommands()) {
      switch (c) {
        case KeyCommand::Screenshot:
          *screenshotNow = true;
          break;
        case KeyCommand::OpenFile:
          openDialog();
          break;
        default: {
          const int index = int(c) - int(KeyCommand::ViewPlusX);
          showAxisView(kAxisViews[index], fb);
        }
      }
    }
    for (const std::string& path : input_.takeDroppedPaths()) {
      startLoad(path);  // one volume at a time: the first drop wins, others say "still loading"
      break;
    }
  }

  void openDialog() {
    const std::string folder =
        current_.path.empty() ? "" : std::filesystem::path(current_.path).parent_path().string();
    fileDialog_.open(folder);
  }

  void showAxisView(AxisView v, const glm::ivec2& fb) {
    const Volume& volume = *current_.volume;
    controller_.setCamera(cameraForAxisView(controller_.camera(), v, volume.worldBoundsMin(),
                                            volume.worldBoundsMax(),
                                            fb.y > 0 ? double(fb.x) / fb.y : 1.0,
                                            volume.patientFrame()));
  }

  void applySessionEdits(const SessionEdits& e, const glm::ivec2& fb, bool* screenshotNow) {
    if (e.openDialog) openDialog();
    if (e.openPath) startLoad(*e.openPath);
    if (e.addBookmark) {
      bookmarks_.list().push_back({*e.addBookmark, controller_.camera()});
      saveBookmarks();
    }
    std::vector<CameraBookmark>& marks = bookmarks_.list();
    if (e.applyBookmark >= 0 && e.applyBookmark < int(marks.size()))
      controller_.setCamera(marks[size_t(e.applyBookmark)].camera);
    if (e.deleteBookmark >= 0 && e.deleteBookmark < int(marks.size())) {
      marks.erase(marks.begin() + e.deleteBookmark);
      saveBookmarks();
    }
    if (e.screenshot) *screenshotNow = true;
    if (e.turntableFrames > 0 && turntable_.total == 0)
      startTurntable(e.turntableFrames, e.turntableFormat, e.turntableFps);
    if (e.cancelTurntable && turntable_.total > 0) {
      turntable_.progress->finish("cancelled");
      turntable_ = WindowTurntable{};
      renderedCamera_ = ~uint64_t(0);
    }
  }

  SessionView sessionView() {
    SessionView v;
    v.recentFiles = &saved_.recentFiles;
    v.bookmarks = &bookmarks_.list();
    v.bookmarksPath = bookmarks_.path();
    v.loading = loadJob_.running();
    v.loadingPath = loadJob_.path();
    v.loadingSeconds = loadJob_.elapsedSeconds();
    if (buildPending_) v.busyText = "building splats for " + current_.name + "...";
    v.turntableDone = turntable_.done;
    v.turntableTotal = turntable_.total;
    v.messages = &messages_.current(now());
    return v;
  }

  // One frame; returns true when the volume was rendered again.
  bool drawFrame() {
    input_.updateViewportSize();
    const glm::ivec2 fb = window_.framebufferSize();
    if (fb.x <= 0 || fb.y <= 0) return false;  // minimised

    pollLoad();
    bool screenshotNow = false;
    applyCommands(fb, &screenshotNow);

    imgui_.beginFrame();
    Camera camera = controller_.camera();
    const PanelEdits edits = panel_.draw(settings_, camera, levelOfDetail_, frameStats_);
    if (edits.camera) controller_.setCamera(camera);
    if (edits.resetCamera) controller_.reset();
    if (edits.axisView) showAxisView(*edits.axisView, fb);
    if (edits.settings) ++settingsRevision_;
    if (const TransferFunction* tf = liveTf_.drawAndApply(lod_, settings_.classification))
      current_.tf = *tf;
    switchRendererIfAsked();
    applySessionEdits(session_.draw(sessionView()), fb, &screenshotNow);
    if (const auto chosen = fileDialog_.draw()) startLoad(*chosen);

    bool rendered = false;
    const bool stale = !hasImage_ || renderedCamera_ != controller_.revision() ||
                       renderedSettings_ != settingsRevision_ || renderedSize_ != fb ||
                       renderedTf_ != liveTf_.revision();
    if (turntable_.total > 0) {
      turntableFrame(fb);
      rendered = true;
    } else if (buildPending_) {
      // This frame shows "building splats"; the next one does the work.
      buildPending_ = false;
    } else if (!hasImage_) {
      TerminalProgress note("ewaview: building splats for " + current_.name + ",");
      const double ms = renderLevel(0, controller_.camera(), fb);
      policy_.startFromFullQuality(ms);
      // The coarse levels classify now, while the user looks at the first picture.
      lod_.warmUp(controller_.camera(), settings_);
      frameStats_.gpuBytes = lod_.gpuBytes();
      char text[64];
      std::snprintf(text, sizeof text, "%zu splats, first frame %.0f ms",
                    frameStats_.render.splatsTotal, ms);
      note.finish(text);
      rendered = true;
    } else if (stale) {
      // Moving: the coarse level the policy picked (full quality with the switch off).
      const int level = levelOfDetail_ ? policy_.movingLevel() : 0;
      const double ms = renderLevel(level, controller_.camera(), fb);
      if (levelOfDetail_) policy_.reportMovingFrame(level, ms);
      if (!config_.recordCameraPath.empty())
        recorded_ += cameraStepLine(controller_.camera()) + "\n";
      lastChange_ = Clock::now();
      rendered = true;
    } else if (refineDue() || fullSplatsArrived_) {
      renderLevel(0, controller_.camera(), fb);
      rendered = true;
    }
    fullSplatsArrived_ = false;
    if (printLayout_ && rendered) {  // for the scripted window test: which level is on screen
      std::printf("frame level %d\n", lod_.lastLevel());
      std::fflush(stdout);
    }
    if (screenshotNow) screenshot(fb);

    presenter_.present(lod_.outputTexture(), lod_.imageWidth(), lod_.imageHeight(), fb.x, fb.y);
    imgui_.render();
    window_.swapBuffers();
    // ImGui decides what it captures while building the frame; the next events obey that.
    input_.setUiCapture(imgui_.wantsMouse(), imgui_.wantsKeyboard());
    return rendered;
  }

  platform::GlfwWindowContext& window_;
  ViewerConfig config_;
  ViewerSettings saved_;
  Clock::time_point epoch_ = Clock::now();
  gl::ShaderLibrary shaders_;
  LoadedVolume current_;
  LodRenderer lod_;
  RendererKind rendererKind_ = RendererKind::Splat;
  std::string renderError_;  // the last render failure, until a render succeeds
  LodPolicy policy_;
  ImagePresenter presenter_;
  CameraController controller_;
  RenderSettings settings_;
  WindowInput input_;
  ImGuiLayer imgui_;
  ControlPanel panel_;
  SessionPanel session_;
  LiveTransferFunction liveTf_;  // after current_ and lod_: its worker ends before they go
  FileDialog fileDialog_;
  StatusMessages messages_;
  VolumeLoadJob loadJob_;
  BookmarkStore bookmarks_;
  WindowTurntable turntable_;
  std::string recorded_;  // camera path lines, when recording

  FrameStats frameStats_;
  bool levelOfDetail_ = true;
  bool printLayout_ = false;
  bool fullSplatsArrived_ = false;
  uint64_t renderedTf_ = 0;
  bool hasNvx_ = false;
  bool buildPending_ = false;
  uint64_t settingsRevision_ = 0;
  bool hasImage_ = false;
  uint64_t renderedCamera_ = 0;
  uint64_t renderedSettings_ = 0;
  glm::ivec2 renderedSize_{0, 0};
  Clock::time_point lastChange_ = Clock::now();
};

}  // namespace

int runViewer(LoadedVolume initial, const ViewerConfig& config) {
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
  Viewer viewer(*window, std::move(initial), config);
  viewer.run();
  viewer.saveSettings();
  viewer.saveRecording();
  return 0;
}

}  // namespace ewa
