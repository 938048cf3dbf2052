// ViewerWindow's pictures written to files: screenshots, turntables, the recorded camera path.
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

void ViewerWindow::screenshot(const glm::ivec2& fb) {
  try {
    const glm::ivec2 size = captureSize(fb);
    // Always the full-quality picture, even if a coarse one is on screen; a larger one is
    // drawn for the file, and the window's drawn again after it.
    if (size != fb) {
      renderLevel(0, controller_.camera(), size);
      renderedCamera_ = ~uint64_t(0);
    } else if (!hasImage_ || lod_.lastLevel() != 0) {
      renderLevel(0, controller_.camera(), fb);
    }
    if (!renderError_.empty()) {  // shown in the window already: no stale picture written
      error("no screenshot: " + renderError_);
      return;
    }
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

// One turntable frame; ends the turntable after the last one.
void ViewerWindow::turntableFrame(const glm::ivec2& fb) {
  WindowTurntable& t = turntable_;
  const std::string file = t.sink->fileOf(t.done);
  try {
    const glm::ivec2 size = captureSize(fb);
    if (t.tour.empty()) {
      renderLevel(0, turntableCamera(t.start, t.done, t.total), size);
    } else {
      // The stop's crop box and planes for this frame only; the panel's come back after
      // (renderLevel reports a failed render itself, it does not throw).
      const TourStop stop = tourFrame(t.tour, t.done, t.total);
      const ClipRegion own = std::exchange(settings_.clip, stop.clip);
      renderLevel(0, stop.camera, size);
      settings_.clip = own;
    }
    renderedCamera_ = ~uint64_t(0);  // the view on screen is not the controller's camera
    // A failed frame ends the turntable, as a failed screenshot writes nothing: never the
    // picture before it in its place.
    if (!renderError_.empty()) throw std::runtime_error("turntable stopped: " + renderError_);
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
    info("saved " + std::to_string(t.total) + " frames in " + t.sink->description());
    t = WindowTurntable{};
  }
}

}  // namespace ewa
