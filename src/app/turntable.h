// Headless turntables and tours: N frames over 360 degrees about the view-up axis, or through
// the camera bookmarks, as PNGs or a video.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/headless_session.h"
#include "app/options.h"
#include "app/scene.h"
#include "app/scene_render.h"
#include "core/camera_tour.h"
#include "core/camera_views.h"
#include "io/frame_sink.h"

namespace ewa {

// Renders options.turntable frames with the options' camera and settings and writes them as
// options.output names them (a %d pattern or a folder, see io/frame_names.h, or an .mp4/.webm
// video at options.fps), with the renderer --renderer names. Progress goes to
// the terminal. Throws on failure ("path: problem").
void renderTurntable(const Scene& scene, const Options& options);

// The frame loop of turntables and tours (the command line's and Python's): `count` frames
// rendered with `session` into `sink` and finished, frame f seen as `view(f)` says (its camera
// and clip region; `options` give the rest), `beforeFrame(f)` called first when given. Returns
// the renderer's notes, one per frame that had one. `layers`: the volume, or the channels
// overlaid (renderLayers).
std::vector<std::string> renderViews(HeadlessSession& session, FrameSink& sink,
                                     const std::vector<RenderLayer>& layers, const Options& options,
                                     int count, const std::function<TourStop(int)>& view,
                                     const std::function<void(int)>& beforeFrame = {});

// The stops of a tour: the bookmarks in `bookmarks`, else where the window keeps the volume
// file's: NAME.bookmarks.json beside it, else (a read-only folder) under `configDir`'s
// bookmarks/ (a volume made here, named `name`: only there, as the window keeps it). Throws
// "path: problem" for a missing or bad file or one of fewer than two bookmarks.
std::vector<TourStop> loadTourStops(const std::string& bookmarks, const std::string& volumeFile,
                                    const std::string& name, const std::string& configDir);

// Renders options.tour frames through the camera bookmarks (options.bookmarks, else the
// volume's NAME.bookmarks.json; tourFrame), each with its bookmark's crop box and planes, and
// writes them as renderTurntable does. Throws "path: problem" for a missing or bad bookmarks
// file or one of fewer than two bookmarks.
void renderTour(const Scene& scene, const Options& options);

}  // namespace ewa
