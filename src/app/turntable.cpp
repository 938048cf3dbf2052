// Headless turntables and tours: one frame loop (camera path, sink, progress) for ewaview,
// ewaview-mpi and Python; ewaview's frames drawn by one HeadlessSession.
#include "app/turntable.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app/headless.h"
#include "app/headless_session.h"
#include "core/camera_tour.h"
#include "io/camera_bookmarks.h"
#include "io/frame_sink.h"
#include "io/terminal_progress.h"
#include "io/viewer_settings.h"

namespace ewa {

namespace {

// One process's frames: the session's renderer draws the layers under the stop's clip region.
DrawFrame sessionDraw(HeadlessSession& session, const std::vector<RenderLayer>& layers,
                      const Options& o) {
  return [&session, &layers, &o](int, const TourStop& stop, Image8* picture, std::string* note) {
    RenderSettings settings = o.render;
    settings.clip = stop.clip;
    *picture = renderLayers(session, layers, stop.camera, settings, o.width, o.height);
    *note = session.takeNote();
    return true;
  };
}

// Renders the frames of `path` into the sink --output names.
void renderFrames(const Scene& scene, const Options& o, const FramePath& path) {
  refuseToOverwriteInputs(o.output, scene, o);
  // The sink checks or makes its folder or file first, so a bad path fails before rendering.
  const std::unique_ptr<FrameSink> sink = openFrameSink(o.output, path.count, o.fps);
  // A frame's name may be a slice of the input stack (-o slices/ of the slices' own folder).
  for (int f = 0; f < path.count; ++f) refuseToOverwriteInputs(sink->fileOf(f), scene, o);
  HeadlessSession session(o.backend, o.shaderDir);
  session.setAxes(o.axes);
  const std::vector<RenderLayer> layers = sceneLayers(scene);
  writeFrames(path, sink.get(), "ewaview", sessionDraw(session, layers, o));
}

}  // namespace

FramePath framePath(const Options& o, const Camera& start, const std::string& volumeFile,
                    const std::string& name) {
  FramePath path;
  if (o.tour > 0) {
    auto stops = std::make_shared<const std::vector<TourStop>>(loadTourStops(
        o.bookmarks, volumeFile, name, o.configDir.empty() ? defaultConfigDir() : o.configDir));
    path.count = o.tour;
    path.what = "tour";
    path.view = [stops, count = o.tour](int f) { return tourFrame(*stops, f, count); };
  } else {
    path.count = o.turntable;
    path.what = "turntable";
    path.view = [start, clip = o.render.clip, count = o.turntable](int f) {
      return TourStop{turntableCamera(start, f, count), clip};
    };
  }
  return path;
}

std::vector<std::string> runFrames(const FramePath& path, FrameSink* sink, const DrawFrame& draw,
                                   const std::function<void(int)>& beforeFrame,
                                   const AnyFailed& anyFailed, bool* stopped) {
  std::vector<std::string> notes;
  if (stopped) *stopped = true;
  for (int f = 0; f <= path.count; ++f) {
    std::string error;
    bool go = true;
    try {
      if (f == path.count) {
        if (sink) sink->finish();
      } else {
        if (beforeFrame) beforeFrame(f);
        Image8 picture;
        std::string note;
        go = draw(f, path.view(f), &picture, &note);
        if (go && sink) sink->add(picture, f);
        if (!note.empty()) notes.push_back(std::move(note));
      }
    } catch (const std::exception& e) {
      if (!anyFailed) throw;
      error = e.what();
      if (error.empty()) error = "a frame failed";
    }
    // A draw that stops has stopped every process alike; an error elsewhere is agreed on.
    if (!go || (anyFailed && anyFailed(error))) return notes;
  }
  if (stopped) *stopped = false;
  return notes;
}

bool writeFrames(const FramePath& path, FrameSink* sink, const std::string& program,
                 const DrawFrame& draw, const AnyFailed& anyFailed) {
  std::unique_ptr<TerminalProgress> progress;
  if (sink) progress = std::make_unique<TerminalProgress>(program + ": " + path.what);
  const auto begin = std::chrono::steady_clock::now();
  bool stopped = false;
  // Notes are said after the progress line, not through it.
  const std::vector<std::string> notes = runFrames(
      path, sink, draw,
      [&](int f) {
        if (progress) progress->update(f + 1, path.count, sink->fileOf(f));
      },
      anyFailed, &stopped);
  if (!progress || stopped) return !stopped;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  char note[96];
  std::snprintf(note, sizeof note, "%d frames in %.1f s", path.count, s);
  progress->finish(note);
  for (const std::string& line : notes)
    std::fprintf(stderr, "%s: %s\n", program.c_str(), line.c_str());
  return true;
}

std::vector<std::string> renderViews(HeadlessSession& session, FrameSink& sink,
                                     const std::vector<RenderLayer>& layers, const Options& o,
                                     int count, const std::function<TourStop(int)>& view,
                                     const std::function<void(int)>& beforeFrame) {
  return runFrames(FramePath{count, "", view}, &sink, sessionDraw(session, layers, o), beforeFrame);
}

void renderTurntable(const Scene& scene, const Options& o) {
  renderFrames(scene, o, framePath(o, initialCamera(scene.volume, o), o.file, scene.name));
}

std::vector<TourStop> loadTourStops(const std::string& bookmarks, const std::string& volumeFile,
                                    const std::string& name, const std::string& configDir) {
  const BookmarkPlaces places = bookmarkPlaces(volumeFile, name, configDir);
  const std::string path = !bookmarks.empty() ? bookmarks : places.read();
  if (path.empty())
    throw std::runtime_error(name +
                             ": --tour needs --bookmarks FILE (no settings folder to "
                             "find the window's bookmarks in)");
  if (!std::filesystem::exists(path)) {
    const bool both = bookmarks.empty() && !places.beside.empty() && !places.fallback.empty();
    throw std::runtime_error(path + ": no such bookmarks file" +
                             (both ? " (nor " + places.fallback + ")" : std::string()) +
                             "; add views in the window's \"Camera bookmarks\", or give "
                             "--bookmarks FILE");
  }
  const std::vector<TourStop> stops = tourStopsOf(loadBookmarks(path));
  if (stops.size() < 2)
    throw std::runtime_error(path + ": a tour needs two bookmarks or more (it holds " +
                             std::to_string(stops.size()) + ")");
  return stops;
}

void renderTour(const Scene& scene, const Options& o) {
  renderFrames(scene, o, framePath(o, initialCamera(scene.volume, o), o.file, scene.name));
}

}  // namespace ewa
