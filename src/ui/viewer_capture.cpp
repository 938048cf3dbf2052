// ViewerWindow's pictures written to files: screenshots, turntables, the recorded camera path.
#include <chrono>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "core/camera_path.h"
#include "io/atomic_file.h"
#include "io/png_io.h"
#include "ui/viewer_window.h"

namespace ewa {

namespace {
// A capture's start (its partition) this quick leaves its UI frame room for the first step.
constexpr double kQuickStartMs = 2.0;
}  // namespace

// The cameras of the moving frames, replayable by ewaview-interact-bench --path.
void ViewerWindow::saveRecording() {
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

// The size of pictures written: the window's times the panel's "size" (capture_scale), each
// side at most kMaxCaptureSide.
glm::ivec2 ViewerWindow::captureSize(const glm::ivec2& fb) const {
  constexpr int kMaxCaptureSide = 16384;
  return glm::min(fb * saved_.captureScale, glm::ivec2(kMaxCaptureSide));
}

bool ViewerWindow::shotPathPromised(const std::string& path) const {
  const std::string p = std::filesystem::absolute(path).lexically_normal().string();
  if ((capture_.active && capture_.path == p) || (shotWrite_.valid() && shotPath_ == p))
    return true;
  for (const PendingCapture& q : queuedShots_)
    if (q.path == p) return true;
  return false;
}

void ViewerWindow::screenshot(const glm::ivec2& fb) {
  if (!renderError_.empty()) {  // shown in the window already: no stale picture written
    error("no screenshot: " + renderError_);
    return;
  }
  PendingCapture c;
  c.active = true;
  c.camera = controller_.camera();
  c.clip = settings_.clip;
  c.size = captureSize(fb);
  // A name no file has yet, nor one promised to a screenshot not written yet (within the same
  // second they would share it).
  c.path = std::filesystem::absolute(
               screenshotFileName(saved_.screenshotDir, current_.name, std::time(nullptr),
                                  [this](const std::string& p) { return shotPathPromised(p); }))
               .lexically_normal()
               .string();
  c.cameraRevision = controller_.revision();
  c.settingsRevision = settingsRevision_;
  c.tfRevision = liveTf_.revision();
  if (capturing()) {
    // Another capture is being drawn or waits: this view's picture follows them (before the
    // turntable's next frame).
    queuedShots_.push_back(std::move(c));
    info("screenshot queued (" + std::to_string(queuedShots_.size()) + " waiting)");
    return;
  }
  // Full quality of this view at this size on screen: written now. Else it is refined over the
  // next UI frames (a coarse picture on screen, a refinement under way, a larger size), never
  // drawn whole in one frame (on llvmpipe far longer than a UI frame may take).
  const bool onScreen = hasImage_ && lod_.lastLevel() == 0 && !refinement_.active() &&
                        lod_.imageWidth() == c.size.x && lod_.imageHeight() == c.size.y &&
                        renderedCamera_ == c.cameraRevision &&
                        renderedSettings_ == c.settingsRevision && renderedTf_ == c.tfRevision;
  if (!onScreen) {
    // The window's own refinement of this very view (any change since would have cancelled it):
    // the capture carries it on.
    c.started = refinement_.active() && c.size == fb;
    c.startedTfRevision = c.tfRevision;
    capture_ = std::move(c);
    return;
  }
  try {
    writeScreenshot(c.path, lod_.last().readImage());
  } catch (const std::exception& e) {
    error(e.what());
  }
}

void ViewerWindow::startTurntable(int frames, const std::string& format, int fps, bool tour) {
  std::vector<TourStop> stops;
  if (tour) {
    stops = tourStopsOf(bookmarks_.list());
    if (stops.size() < 2) {
      error("a tour needs two camera bookmarks or more");
      return;
    }
  }
  std::string folder =
      std::filesystem::absolute(
          screenshotFileName(saved_.screenshotDir, current_.name, std::time(nullptr)))
          .lexically_normal()
          .string();
  folder = folder.substr(0, folder.size() - 4) + (tour ? "-tour" : "-turntable");
  try {
    turntable_.sink = openFrameSink(format == "png" ? folder : folder + "." + format, frames, fps);
  } catch (const std::exception& e) {
    error(e.what());
    return;
  }
  turntable_.total = frames;
  turntable_.done = 0;
  turntable_.start = controller_.camera();
  turntable_.tour = std::move(stops);
  turntable_.progress =
      std::make_unique<TerminalProgress>(tour ? "ewaview: tour" : "ewaview: turntable");
}

void ViewerWindow::writeScreenshot(const std::string& path, Image8 image) {
  pollScreenshot(/*wait=*/true);  // the one before first: its message, then this one's
  shotPath_ = path;
  shotWrite_ =
      std::async(std::launch::async, [path, image = std::move(image)] { writePng(path, image); });
}

void ViewerWindow::pollScreenshot(bool wait) {
  if (!shotWrite_.valid()) return;
  if (!wait && shotWrite_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  try {
    shotWrite_.get();
    info("saved screenshot " + shotPath_);
  } catch (const std::exception& e) {
    error(e.what());
  }
}

void ViewerWindow::nextTurntableCapture(const glm::ivec2& fb) {
  const WindowTurntable& t = turntable_;
  PendingCapture c;
  c.active = true;
  c.size = captureSize(fb);
  if (t.tour.empty()) {
    c.camera = turntableCamera(t.start, t.done, t.total);
    c.clip = settings_.clip;
  } else {
    // The stop's crop box and planes, for this frame only.
    const TourStop stop = tourFrame(t.tour, t.done, t.total);
    c.camera = stop.camera;
    c.clip = stop.clip;
  }
  capture_ = std::move(c);
}

bool ViewerWindow::captureStep(const glm::ivec2& fb, bool activity) {
  if (!capture_.active) {
    if (!queuedShots_.empty()) {
      capture_ = std::move(queuedShots_.front());
      queuedShots_.pop_front();
    } else if (turntable_.total > 0) {
      nextTurntableCapture(fb);
    } else {
      return false;
    }
  }
  // A transfer-function edit's full splats still on the worker: they come first, as for the
  // window's own refinement (the renderer holds the old set until then).
  if (liveTf_.building() || splatsUploaded_) return false;
  try {
    // Not begun, its refinement abandoned since (another volume, another renderer) or drawn
    // with a transfer function edited since.
    if (!capture_.started || !refinement_.active() ||
        capture_.startedTfRevision != liveTf_.revision() || fullSplatsArrived_) {
      RenderSettings s = settings_;
      s.clip = capture_.clip;
      // Another classification (shading switched on, say) is built on the worker first, once,
      // as for the window's refinement; should that fail, the start classifies itself.
      if (askForFullSplats(s)) return false;
      capture_.startedTfRevision = liveTf_.revision();
      refinement_.start(lod_, capture_.camera, s, capture_.size);
      capture_.started = true;
      renderError_.clear();
      // A quick start (a GPU's partition) leaves this frame room for the first step: a
      // turntable's frame then takes one UI frame where it fits one, as drawn whole it did.
      if (refinement_.lastStepMs() > kQuickStartMs) return false;
    }
    if (printLayout_) {  // the scripted window test: captures are drawn in steps
      std::printf("capture step\n");
      std::fflush(stdout);
    }
    if (!refinement_.step(lod_, refinement_.presentsStep(activity))) return false;
  } catch (const std::exception& e) {
    refinement_.cancel();
    renderFailed(e, fb);
    if (capture_.path.empty())
      stopTurntable("turntable stopped: " + renderError_);
    else
      error("no screenshot: " + renderError_);
    capture_ = PendingCapture{};
    return true;
  }
  finishCapture(fb);
  return true;
}

void ViewerWindow::finishCapture(const glm::ivec2& fb) {
  const PendingCapture c = std::exchange(capture_, PendingCapture{});
  noteFrameStats(0);
  // A screenshot of the view still on screen is the window's full picture too (a larger one
  // shown scaled down, supersampled); any other shows a view that is not the controller's:
  // drawn again after.
  const bool current = !c.path.empty() && c.cameraRevision == controller_.revision() &&
                       c.settingsRevision == settingsRevision_ &&
                       c.tfRevision == liveTf_.revision();
  if (current)
    noteImage(fb);
  else
    renderedCamera_ = ~uint64_t(0);
  if (c.path.empty()) {
    turntableFrameDone(lod_.last().readImage());
    return;
  }
  try {
    writeScreenshot(c.path, lod_.last().readImage());
  } catch (const std::exception& e) {
    error(e.what());
  }
}

void ViewerWindow::turntableFrameDone(Image8 image) {
  WindowTurntable& t = turntable_;
  if (t.total == 0) return;  // cancelled meanwhile
  const std::string file = t.sink->fileOf(t.done);
  try {
    t.sink->add(std::move(image), t.done);
    if (t.done + 1 == t.total) t.sink->finish();
  } catch (const std::exception& e) {
    stopTurntable(e.what());
    return;
  }
  ++t.done;
  t.progress->update(t.done, t.total, file);
  if (t.done == t.total) {
    t.progress->finish("done");
    info("saved " + std::to_string(t.total) + " frames in " + t.sink->description());
    t = WindowTurntable{};
  }
}

// Ends the turntable before its last frame (an error, or cancelled: `why` empty).
void ViewerWindow::stopTurntable(const std::string& why) {
  if (turntable_.total == 0) return;
  if (why.empty())
    turntable_.progress->finish("cancelled");
  else
    error(why);
  turntable_ = WindowTurntable{};
  if (capture_.active && capture_.path.empty()) {
    capture_ = PendingCapture{};
    refinement_.cancel();
  }
  renderedCamera_ = ~uint64_t(0);
}

}  // namespace ewa
