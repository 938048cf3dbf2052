// Headless turntables and tours: one HeadlessSession (the --renderer's renderer), N views, one
// sink.
#include "app/turntable.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
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

// Renders `count` frames, frame f seen as `view(f)` says, into the sink --output names.
void renderFrames(const Scene& scene, const Options& o, int count, const char* what,
                  const std::function<TourStop(int)>& view) {
  refuseToOverwriteInputs(o.output, scene, o);
  // The sink checks or makes its folder or file first, so a bad path fails before rendering.
  const std::unique_ptr<FrameSink> sink = openFrameSink(o.output, count, o.fps);
  // A frame's name may be a slice of the input stack (-o slices/ of the slices' own folder).
  for (int f = 0; f < count; ++f) refuseToOverwriteInputs(sink->fileOf(f), scene, o);
  HeadlessSession session(o.backend, o.shaderDir);
  session.setAxes(o.axes);
  TerminalProgress progress(std::string("ewaview: ") + what);
  const auto begin = std::chrono::steady_clock::now();
  // Notes are said after the progress line, not through it.
  const std::vector<std::string> notes =
      renderViews(session, *sink, sceneLayers(scene), o, count, view,
                  [&](int f) { progress.update(f + 1, count, sink->fileOf(f)); });
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  char note[96];
  std::snprintf(note, sizeof note, "%d frames in %.1f s", count, s);
  progress.finish(note);
  for (const std::string& line : notes) std::fprintf(stderr, "ewaview: %s\n", line.c_str());
}

}  // namespace

std::vector<std::string> renderViews(HeadlessSession& session, FrameSink& sink,
                                     const std::vector<RenderLayer>& layers, const Options& o,
                                     int count, const std::function<TourStop(int)>& view,
                                     const std::function<void(int)>& beforeFrame) {
  std::vector<std::string> notes;
  RenderSettings settings = o.render;
  for (int f = 0; f < count; ++f) {
    if (beforeFrame) beforeFrame(f);
    const TourStop stop = view(f);
    settings.clip = stop.clip;
    sink.add(renderLayers(session, layers, stop.camera, settings, o.width, o.height), f);
    if (std::string note = session.takeNote(); !note.empty()) notes.push_back(std::move(note));
  }
  sink.finish();
  return notes;
}

void renderTurntable(const Scene& scene, const Options& o) {
  const Camera start = initialCamera(scene.volume, o);
  renderFrames(scene, o, o.turntable, "turntable", [&](int f) {
    return TourStop{turntableCamera(start, f, o.turntable), o.render.clip};
  });
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
  const std::vector<TourStop> stops = loadTourStops(
      o.bookmarks, o.file, scene.name, o.configDir.empty() ? defaultConfigDir() : o.configDir);
  renderFrames(scene, o, o.tour, "tour", [&](int f) { return tourFrame(stops, f, o.tour); });
}

}  // namespace ewa
