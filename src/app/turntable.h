// Headless turntables and tours: N frames over 360 degrees about the view-up axis, or through
// the camera bookmarks, as PNGs or a video; the frame loop ewaview and ewaview-mpi share.
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

// A camera path of `count` frames, frame f seen as view(f) says (its camera and clip region).
struct FramePath {
  int count = 0;
  std::string what;  // "turntable" or "tour": the progress line's label
  std::function<TourStop(int)> view;
};

// The path options ask for: options.turntable frames about the view-up axis from `start`
// (turntableCamera, the options' clip region), or options.tour frames through the camera
// bookmarks (loadTourStops of options.bookmarks, `volumeFile` and `name`; tourFrame), each with
// its bookmark's crop box and planes. Throws "path: problem" as loadTourStops does.
FramePath framePath(const Options& options, const Camera& start, const std::string& volumeFile,
                    const std::string& name);

// Draws frame `frame` seen from `stop` into `picture` (left without pixels where this process
// writes nothing: ewaview-mpi's ranks other than 0) and the renderer's note of the frame into
// `note`. Returns false to stop every process's loop after the reason was said (ewaview-mpi's
// collective frame failing); throws on failure otherwise.
using DrawFrame =
    std::function<bool(int frame, const TourStop& stop, Image8* picture, std::string* note)>;

// Whether any process failed after a frame, given this process's error ("" when none), the
// failure said once: ewaview-mpi's ranks agree on it so that all stop together.
using AnyFailed = std::function<bool(const std::string& error)>;

// The frame loop of turntables and tours (the command line's, ewaview-mpi's and Python's): for
// each of path.count frames, `beforeFrame(f)` when given, then `draw`, then the picture into
// `sink` when this process has one (null elsewhere); the sink is finished after the last frame.
// With `anyFailed`, every process calls it after each frame and at the end with what failed
// there, and the loop stops on every process when it says so; without it errors are thrown.
// Returns the frames' notes (one per frame that had one) and, in `stopped`, whether it stopped
// early.
std::vector<std::string> runFrames(const FramePath& path, FrameSink* sink, const DrawFrame& draw,
                                   const std::function<void(int)>& beforeFrame = {},
                                   const AnyFailed& anyFailed = {}, bool* stopped = nullptr);

// runFrames with the command line's terminal output where `sink` is given: the progress line
// ("PROGRAM: turntable 3/36 FILE"), its closing note ("36 frames in 4.1 s") and then the
// frames' notes ("PROGRAM: ..."). Returns false when the loop stopped early.
bool writeFrames(const FramePath& path, FrameSink* sink, const std::string& program,
                 const DrawFrame& draw, const AnyFailed& anyFailed = {});

// Renders options.turntable frames with the options' camera and settings and writes them as
// options.output names them (a %d pattern or a folder, see io/frame_names.h, or an .mp4/.webm
// video at options.fps), with the renderer --renderer names. Progress goes to
// the terminal. Throws on failure ("path: problem").
void renderTurntable(const Scene& scene, const Options& options);

// Python's frame loop: `count` frames rendered with `session` into `sink` and finished, frame f
// seen as `view(f)` says (its camera and clip region; `options` give the rest), `beforeFrame(f)`
// called first when given. Returns the renderer's notes, one per frame that had one. `layers`:
// the volume, or the channels overlaid (renderLayers).
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
