// runViewer and the viewer's loop: events, level-of-detail rendering, progressive refinement, swap.
#include "ui/viewer.h"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "core/camera_path.h"
#include "core/stopwatch.h"
#include "gl/gpu_memory.h"
#include "io/atomic_file.h"
#include "io/side_file.h"
#include "render/renderer_factory.h"
#include "render/splat_renderer.h"
#include "ui/viewer_window.h"

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
// Renderer time a UI frame gives the full-quality refinement at most, and the UI frame time
// to stay under meanwhile (the bound is 100 ms; the target leaves room in it for the
// swap and the panel, which are slow on llvmpipe).
constexpr double kRefineBudgetMs = 30.0;
constexpr double kRefineFrameTargetMs = 50.0;
// The most a UI frame waits for a new size's images made on a worker (movingImagesReady): the
// frame still presents the stretched picture at the new size, itself costly on llvmpipe.
constexpr double kImageWaitMs = 15.0;

bool envFlag(const char* name) {
  const char* value = std::getenv(name);
  return value && *value == '1';
}

// EWAVIEW_REFINE_BUDGET_MS (tests): a smaller budget makes refinement take many frames.
double refineBudgetMs() {
  const char* value = std::getenv("EWAVIEW_REFINE_BUDGET_MS");
  const double ms = value ? std::atof(value) : 0.0;
  return ms > 0.0 ? ms : kRefineBudgetMs;
}

}  // namespace

ViewerWindow::ViewerWindow(platform::GlfwWindowContext& window, LoadedVolume initial,
                           const ViewerConfig& config)
    : window_(window),
      config_(config),
      saved_(config.saved),
      shaders_(config.shaderDir),
      uploadContext_(window.createUploadContext()),
      lod_([this] { return makeRenderer(); }, uploadContext_.get()),
      refinement_(refineBudgetMs(), kRefineFrameTargetMs),
      controller_(config.camera),
      settings_(config.settings),
      input_(window.window(), controller_),
      imgui_(window.window()),
      panel_(initial.name, *initial.volume) {
  if (!config_.configDir.empty()) {
    try {
      imgui_.loadLayout(readSideFile(imguiIniPathIn(config_.configDir), "window layout file"));
    } catch (const std::exception&) {
      // No layout saved yet: ImGui's defaults.
    }
  }
  rendererKind_ = settings_.renderer;  // lod_ makes renderers of this kind
  printLayout_ = envFlag("EWAVIEW_PRINT_LAYOUT");
  panel_.setPrintLayout(printLayout_);
  session_.setPrintLayout(printLayout_);
  imgui_.setKeyLog(printLayout_);
  frameLog_ = envFlag("EWAVIEW_FRAME_LOG");
  levelOfDetail_ = saved_.levelOfDetail;
  axes_ = saved_.axes;
  watchFile_ = config.watch;
  hasNvx_ = gl::queryGpuMemory().has_value();
  if (initial.coarse.levels.empty() && !config_.rendererFactory)
    initial.coarse = buildLodVolumes(*initial.volume);
  adopt(std::move(initial), /*newCamera=*/false);
  // The worker classifies the full level while this thread makes the renderers ready and draws
  // the first picture.
  if (levelOfDetail_) requestFullLevel();
  // Shader failures throw here: one line, exit 1. The window's first full-quality frame then
  // finds its programs, images and tables made (made there, they would stall its first
  // refinement step well past a UI frame's budget).
  const glm::ivec2 fb = window_.framebufferSize();
  lod_.prepareFullLevel(settings_, fb.x, fb.y);
}

void ViewerWindow::run() {
  int quietFrames = 0;
  while (!window_.shouldClose()) {
    const bool refining = refinement_.active();
    const bool warmUp = warmUpDue();
    const double wait =
        quietFrames < kFramesAfterActivity || refining || warmUp || imgui_.keysHeld()
            ? 0.0
            : waitSeconds();
    if (wait > 0.0)
      glfwWaitEventsTimeout(wait);
    else
      glfwPollEvents();
    const Clock::time_point start = Clock::now();
    // `|`, not `||`: both must run (take the flag and swap in a finished splat set).
    const bool active = input_.takeActivity() | takeBuiltSplats();
    // An idle window wakes every kIdleWaitSeconds, often enough to see its file change.
    if (watchFile_ && !loadJob_.running() && fileWatch_.changed(now())) reload();
    const bool due = busy() || refineDue() || refinement_.active() || fullSplatsArrived_ ||
                     warmUp || !messages_.current(now()).empty() || imgui_.keysHeld();
    if (!active && !due && quietFrames >= kFramesAfterActivity) continue;

    // Before the frame: a finished splat set's upload or a reload, not the moving level's cost.
    const double beforeDrawMs = millisecondsSince(start);
    const bool rendered = drawFrame(active);
    const double ms = millisecondsSince(start);
    if (movingLevelDrawn_ >= 0)
      policy_.reportMovingFrame(movingLevelDrawn_, movingRenderMs_,
                                ms - beforeDrawMs - movingRenderMs_);
    movingLevelDrawn_ = -1;
    frameStats_.frameMs = ms;
    refinement_.reportFrame(ms);
    logFrame(ms);
    // A new image changes the statistics shown, so draw at least one more frame.
    quietFrames = (active || rendered) ? 0 : quietFrames + 1;
  }
  pollScreenshot(/*wait=*/true);  // a screenshot still being written is finished and reported
}

double ViewerWindow::now() const {
  return std::chrono::duration<double>(Clock::now() - epoch_).count();
}

bool ViewerWindow::busy() const {
  // A save on its worker too: the panel counts its seconds, and its end is shown when it comes
  // (an idle window would see it only at its next idle wake).
  return loadJob_.running() || saveJob_.running() || capturing() || shotWrite_.valid() ||
         buildPending_ || liveTf_.building() || imagesPending_ || presentNext_;
}

void ViewerWindow::requestFullLevel() {
  fullBuildFor_ = splatClassification(settings_);
  liveTf_.buildFullLevel(lod_, *fullBuildFor_);
  fullLevelAsked_ = true;
}

// Coarse levels not drawn yet are warmed up after the first picture, one a frame, while the
// worker builds the full level's splats (beside this thread) or once full quality is shown:
// never in the way of the first picture or of a refinement.
bool ViewerWindow::warmUpDue() const {
  if (!levelOfDetail_ || !hasImage_ || refinement_.active() || !lod_.warmUpPending()) return false;
  if (loadJob_.running() || turntable_.total > 0 || buildPending_) return false;
  return liveTf_.building() || lod_.lastLevel() == 0;  // loading and capturing ruled out above
}

// A coarse image is shown and the quiet time before full quality has passed.
bool ViewerWindow::refineDue() const {
  // A full splat set being built on the worker refines once it is there.
  return hasImage_ && !refineFailed_ && lod_.lastLevel() != 0 && !liveTf_.building() &&
         policy_.shouldRefine(millisecondsSince(lastChange_));
}

double ViewerWindow::waitSeconds() const {
  if (capturing() || buildPending_ || refinement_.active() || imagesPending_) return 0.0;
  if (liveTf_.building()) return kBuildPollSeconds;
  if (hasImage_ && !refineFailed_ && lod_.lastLevel() != 0)
    return std::max(0.0, (policy_.refineDelayMs() - millisecondsSince(lastChange_)) / 1000.0);
  if (loadJob_.running() || saveJob_.running() || shotWrite_.valid()) return kLoadingWaitSeconds;
  return kIdleWaitSeconds;
}

void ViewerWindow::noteImage(const glm::ivec2& fb) {
  hasImage_ = true;
  renderedCamera_ = controller_.revision();
  renderedSettings_ = settingsRevision_;
  renderedSize_ = fb;
  renderedTf_ = liveTf_.revision();
}

// A GL failure (out of memory, a limit, an incomplete framebuffer) keeps the window open: the
// message is shown in the window and printed once, until a change renders again.
void ViewerWindow::renderFailed(const std::exception& e, const glm::ivec2& fb) {
  std::string message = e.what();
  for (char& c : message) c = (c == '\n' || c == '\r') ? ' ' : c;
  if (message != renderError_) error(message + " (the window keeps running)");
  renderError_ = message;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  noteImage(fb);  // retried when the view, settings or size change, not every frame
}

double ViewerWindow::renderLevel(int level, const Camera& camera, const glm::ivec2& fb) {
  const Clock::time_point start = Clock::now();
  refinement_.cancel();  // a whole frame replaces the one being refined
  policySize_ = fb;      // the moving levels' measurements are made at this size from now on
  try {
    lod_.render(level, camera, settings_, fb.x, fb.y);
    renderError_.clear();
  } catch (const std::exception& e) {
    renderFailed(e, fb);
    return millisecondsSince(start);
  }
  const double ms = millisecondsSince(start);
  levelRenderMs_ = ms;
  noteImage(fb);
  noteFrameStats(level);
  frameStats_.refinement = RefinementReport{};  // drawn whole, not refined
  return ms;
}

void ViewerWindow::noteFrameStats(int level) {
  frameStats_.render = lod_.last().stats();
  frameStats_.imageWidth = lod_.imageWidth();
  frameStats_.imageHeight = lod_.imageHeight();
  frameStats_.lodLevel = level;
  frameStats_.gpuBytes = lod_.gpuBytes();
  if (config_.statisticsLines) frameStats_.extraLines = config_.statisticsLines();
  if (hasNvx_) frameStats_.gpuMemory = gl::queryGpuMemory();
}

bool ViewerWindow::askForFullSplats(const RenderSettings& settings) {
  SplatRenderer* full = lod_.fullSplatRenderer();
  const Classification wanted = splatClassification(settings);
  if (!full || !full->needsSplats(wanted) || fullBuildFor_ == wanted) return false;
  fullBuildFor_ = wanted;
  liveTf_.buildFullSplats(lod_, wanted);
  return true;
}

bool ViewerWindow::refine(const glm::ivec2& fb, bool activity) {
  if (!refinement_.active() || fullSplatsArrived_) {
    // Another classification (gradients, surface splats) is built on the worker first, once;
    // refineDue() waits for it. Should that fail, the start below classifies itself.
    if (askForFullSplats(settings_)) return false;
    // The slab partition and the uniforms: this frame's work; the slabs follow in the next
    // frames.
    try {
      refinement_.start(lod_, controller_.camera(), settings_, fb);
    } catch (const std::exception& e) {
      refinement_.cancel();
      refineFailed_ = true;
      renderFailed(e, fb);
      return true;
    }
    if (printLayout_) {
      std::printf("refine start\n");
      std::fflush(stdout);
    }
    return false;
  }
  bool done = false;
  try {
    done = refinement_.step(lod_, refinement_.presentsStep(activity));
  } catch (const std::exception& e) {
    refinement_.cancel();
    refineFailed_ = true;
    renderFailed(e, fb);
    return true;
  }
  if (!done) return false;
  renderError_.clear();
  noteImage(fb);
  const RefinementReport& report = refinement_.last();
  noteFrameStats(0);
  if (calibrate_ && levelOfDetail_) policy_.startFromFullQuality(report.workMs);
  calibrate_ = false;
  if (printLayout_) {
    std::printf("refine done\n");
    std::fflush(stdout);
  }
  return true;
}

void ViewerWindow::logFrame(double ms) {
  frameStats_.refineProgress = refinement_.active() ? refinement_.progress(lod_) : -1.0;
  // A refinement finished with this frame: its report (worst frame included) goes to the panel.
  const RefinementReport& r = refinement_.last();
  const bool finished = r.index != reportedRefinement_ && !refinement_.active();
  if (finished) {
    reportedRefinement_ = r.index;
    frameStats_.refinement = r;
  }
  if (!frameLog_) {
    levelRenderMs_ = -1.0;
    return;
  }
  if (refinement_.active())
    std::fprintf(stderr, "ewaview: frame %.1f ms, refining %.0f%% (step %.1f ms, budget %.0f ms)\n",
                 ms, 100.0 * refinement_.progress(lod_), refinement_.lastStepMs(),
                 refinement_.budgetMs());
  else if (finished)  // the frame of the refinement's last step, its final pass included
    std::fprintf(stderr, "ewaview: frame %.1f ms, level %d (last step %.1f ms)\n", ms,
                 lod_.lastLevel(), refinement_.lastStepMs());
  else if (levelRenderMs_ >= 0.0)  // a level drawn whole: where its time went
    std::fprintf(stderr,
                 "ewaview: frame %.1f ms, level %d (render %.1f ms: classify %.1f, partition "
                 "%.1f, splat %.1f, final %.1f)\n",
                 ms, lod_.lastLevel(), levelRenderMs_, frameStats_.render.classifyMs,
                 frameStats_.render.partitionMs, frameStats_.render.splatMs,
                 frameStats_.render.compositeMs);
  else
    std::fprintf(stderr, "ewaview: frame %.1f ms, level %d\n", ms, lod_.lastLevel());
  levelRenderMs_ = -1.0;
  if (finished)
    std::fprintf(stderr,
                 "ewaview: full quality in %.0f ms over %d frames (renderer %.0f ms), worst "
                 "frame %.1f ms\n",
                 r.wallMs, r.frames, r.workMs, r.worstFrameMs);
}

bool ViewerWindow::movingImagesReady(const glm::ivec2& fb) {
  if (!levelOfDetail_ || fb == renderedSize_) return true;
  if (fb != policySize_) {
    // The moving levels' measurements were made at policySize_.
    if (policySize_.x > 0 && policySize_.y > 0)
      policy_.resized(double(fb.x) * double(fb.y) /
                      (double(policySize_.x) * double(policySize_.y)));
    policySize_ = fb;
  }
  try {
    if (!lod_.prepareImages(policy_.movingLevel(), settings_, fb.x, fb.y, kImageWaitMs))
      imagesPending_ = true;
  } catch (const std::exception&) {
    // Drawing the level says what failed (renderFailed), as it would have without this.
  }
  return !imagesPending_;
}

bool ViewerWindow::drawFrame(bool activity) {
  input_.updateViewportSize();
  const glm::ivec2 fb = window_.framebufferSize();
  if (fb.x <= 0 || fb.y <= 0) return false;  // minimised

  pollLoad();
  pollSave();
  pollScreenshot();
  bool screenshotNow = false;
  applyCommands(fb, &screenshotNow);
  drawPanels(fb, &screenshotNow);

  bool rendered = false;
  bool presentNow = presentNext_;  // presents without a new picture
  presentNext_ = false;
  bool deferPresent = false;  // a new picture presented by the next UI frame
  imagesPending_ = false;     // until movingImagesReady says otherwise
  // A resize under way (another size than the last UI frame's): this frame shows the last
  // picture stretched, and the view is drawn once a frame keeps the size, so a drag through
  // many sizes does not make a set of images at each (on llvmpipe a coarse level's new images
  // and the window's new buffers in one frame overrun the 100 ms bound).
  const bool resizing = hasImage_ && fb != lastFrameSize_;
  lastFrameSize_ = fb;
  const bool stale = !hasImage_ || renderedCamera_ != controller_.revision() ||
                     renderedSettings_ != settingsRevision_ || renderedSize_ != fb ||
                     renderedTf_ != liveTf_.revision();
  if (capturing() && hasImage_) {
    // A screenshot's or turntable's picture, refined in steps; the view catches up after it.
    rendered = captureStep(fb, activity);
  } else if (resizing) {
    refinement_.cancel();  // drawn for the size before
    lastChange_ = Clock::now();
  } else if (buildPending_) {
    // This frame shows "building splats"; the next one does the work.
    buildPending_ = false;
  } else if (!hasImage_ && levelOfDetail_ && !presenter_.stretchWarmedUp()) {
    // A UI frame of its own before the first picture, not presented: the blit that will show
    // that picture compiled (slow on llvmpipe: in the picture's present, or in the window's
    // first frame beside ImGui's set-up, it would push that frame past the bound).
    const int divisor = LodPolicy::level(lod_.coarsestLevel()).imageDivisor;
    presenter_.warmUpStretch(std::max(1, fb.x / divisor), std::max(1, fb.y / divisor));
    deferPresent = true;  // the next frame is drawn (the first picture's)
  } else if (!hasImage_) {
    // The first picture: the coarsest level at once, full quality refines from it (without
    // levels of detail: full quality, whole).
    const int level = levelOfDetail_ ? lod_.coarsestLevel() : 0;
    TerminalProgress note("ewaview: building splats for " + current_.name + ",");
    if (levelOfDetail_) {
      if (!fullLevelAsked_) requestFullLevel();
      fullLevelAsked_ = false;
      // The other coarse levels are readied after this picture (warmUpDue).
    }
    const double ms = renderLevel(level, controller_.camera(), fb);
    // Presented by the next UI frame (the refinement's first, which only starts it): the
    // present and swap beside the level's first frame would push it past the bound on llvmpipe.
    deferPresent = levelOfDetail_;
    if (levelOfDetail_) {
      calibrate_ = true;
      lastChange_ = Clock::now() - std::chrono::seconds(10);  // refine at once
    } else {
      policy_.startFromFullQuality(ms);
    }
    frameStats_.gpuBytes = lod_.gpuBytes();
    char text[96];
    std::snprintf(text, sizeof text, "%zu splats, first frame %.0f ms",
                  frameStats_.render.splatsTotal, ms);
    note.finish(text);
    rendered = true;
  } else if (stale && !movingImagesReady(fb)) {
    // A new size: the stretched picture stays until the moving level's images are made.
    lastChange_ = Clock::now();
    presentNow = true;
  } else if (stale) {
    // Moving: the coarse level the policy picked (full quality with the switch off). Any
    // change abandons the refinement under way.
    const int level = levelOfDetail_ ? policy_.movingLevel() : 0;
    // The first picture at a new size is presented in the next UI frame: llvmpipe compiles the
    // blit of an image of a size new to it at the first present, which costs about as much as
    // drawing the level, and the swap comes on top.
    deferPresent = levelOfDetail_ && fb != renderedSize_;
    movingRenderMs_ = renderLevel(level, controller_.camera(), fb);
    if (levelOfDetail_) movingLevelDrawn_ = level;  // reported with the whole frame's time
    calibrate_ = false;
    refineFailed_ = false;
    if (!config_.recordCameraPath.empty()) recorded_ += cameraStepLine(controller_.camera()) + "\n";
    lastChange_ = Clock::now();
    rendered = true;
  } else if (splatsUploaded_) {
    // This frame put a new splat set in place (copied to the GPU by a worker when it is big):
    // the refinement starts or restarts in the next one.
  } else if (refinement_.active() || refineDue() || fullSplatsArrived_) {
    rendered = refine(fb, activity);
  } else if (warmUpDue()) {
    // Nothing else to do: one step of readying a coarse level, so moving there later does not
    // stall. Best effort: a level that fails says so when it is drawn.
    try {
      lod_.warmUpNext(controller_.camera(), settings_);
    } catch (const std::exception&) {
    }
  }
  if (!splatsUploaded_) fullSplatsArrived_ = false;
  splatsUploaded_ = false;
  if (printLayout_ && rendered) {  // for the scripted window test: which level is on screen
    std::printf("frame level %d\n", lod_.lastLevel());
    std::fflush(stdout);
  }
  if (screenshotNow) screenshot(fb);

  if (deferPresent && !screenshotNow) {
    imgui_.endFrame();
    presentNext_ = true;
  } else if (!rendered && !screenshotNow && !presentNow && !refinement_.presentsStep(activity)) {
    imgui_.endFrame();  // the screen keeps the last presented frame
    // Not in the first picture's frames, already near the bound on llvmpipe without it.
    if (pictureShown_) presenter_.warmUpExactCopy(lod_.outputTexture());
  } else {
    presenter_.present(lod_.outputTexture(), lod_.imageWidth(), lod_.imageHeight(), fb.x, fb.y);
    imgui_.render();
    window_.swapBuffers();
    pictureShown_ = pictureShown_ || hasImage_;
    refinement_.notePresented();
  }
  // ImGui decides what it captures while building the frame; the next events obey that.
  input_.setUiCapture(imgui_.wantsMouse(), imgui_.wantsKeyboard());
  return rendered;
}

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
  ViewerWindow viewer(*window, std::move(initial), config);
  viewer.run();
  viewer.saveSettings();
  viewer.saveRecording();
  return 0;
}

}  // namespace ewa
