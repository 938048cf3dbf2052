// The window's frames drawn by every rank: ClusterLink (rank 0 sends each frame's description and
// draws it with the others), DistributedRenderer (the viewer's Renderer over it) and serveFrames
// (the other ranks' loop).
#pragma once

#include <mpi.h>

#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/frame_description.h"
#include "core/image8.h"
#include "gl/texture.h"
#include "platform/gl_context.h"
#include "render/renderer.h"

namespace ewa::dist {

class DistributedSession;

// Rank 0's end of the frame loop. Frames are collective: draw() returns once every rank drew
// its brick and the composite reached rank 0, so one frame is out at a time and each is the
// newest the caller had.
class ClusterLink {
 public:
  explicit ClusterLink(DistributedSession& session);
  ClusterLink(const ClusterLink&) = delete;
  ClusterLink& operator=(const ClusterLink&) = delete;

  // Sends `frame` to every rank and draws it with them (DistributedSession::render): `picture`
  // gets the composite (premultiplied RGBA floats, bottom row first). False when a rank failed
  // (its one line printed, every other rank out of its loop): nothing is sent after that.
  bool draw(const FrameDescription& frame, std::vector<float>* picture);
  // Ends every rank's loop with `status`; nothing after a failed frame, once only.
  void quit(int status);
  bool failed() const { return failed_; }
  DistributedSession& session() { return session_; }
  // The statistics panel's lines of the last frame: the ranks, their bricks, each one's render
  // and composite times. Any thread, also while draw() runs on another (the last frame's).
  std::vector<std::string> statisticsLines() const;

 private:
  // The lines of the frame just drawn (figures, split and ghosts as draw() left them).
  std::vector<std::string> makeLines(int width, int height, double wallMs) const;

  DistributedSession& session_;
  bool failed_ = false, quitSent_ = false;
  mutable std::mutex linesMutex_;  // the window's thread reads the lines a worker's frame made
  std::vector<std::string> lines_;
};

// Ranks other than 0: receives frame descriptions and draws each with the others until a
// quit. Returns the quit's exit status, or 1 after a frame failed on some rank.
int serveFrames(DistributedSession& session);

// The viewer's renderer on rank 0: each render() is one collective frame through the link,
// finished on the CPU (finishPicture) and shown through a texture. Every level of detail draws
// the ranks' bricks at full resolution; only the image is smaller. setVolume is ignored: each
// rank holds its own brick.
//
// With setWorkerFrames, full-quality frames (beginFrame/stepFrame) are drawn on a worker thread,
// so the window keeps answering while the ranks draw: stepFrame waits for it at most its budget,
// and a beginFrame while a frame is out is kept as the one newest request (the views between are
// never sent). MPI is then called by one thread at a time (MPI_THREAD_SERIALIZED): the worker
// while a frame is out, else the caller's thread; render() and the destructor wait for the worker
// first. Without it every frame is drawn on the caller's thread.
class DistributedRenderer : public Renderer {
 public:
  // `window`: the context the output texture lives in, made current again after each frame
  // (this rank's brick is drawn on a headless context of its own); null: no texture, readImage
  // only. `onFailure`: called once when a frame failed on some rank (the window closes).
  DistributedRenderer(std::shared_ptr<ClusterLink> link, platform::GlContext* window,
                      std::function<void()> onFailure = {});
  // Waits for a frame on the worker (the caller then may use MPI, e.g. ClusterLink::quit).
  ~DistributedRenderer() override;
  DistributedRenderer(const DistributedRenderer&) = delete;
  DistributedRenderer& operator=(const DistributedRenderer&) = delete;

  // Full-quality frames on a worker thread from the frame after the next synchronous one (that
  // one makes this rank's brick renderer and its context on the caller's thread, as GLFW asks).
  // `releaseContext` runs on the worker after each frame: it unbinds the brick's context there,
  // so that the caller's thread may bind it for a synchronous frame.
  void setWorkerFrames(std::function<void()> releaseContext);

  void setVolume(const Volume& /*volume*/) override {}
  void setTransferFunction(const TransferFunction& tf) override { tf_ = tf; }
  // After a failed frame (and for every frame after it): calls onFailure once and keeps the
  // last picture, or throws where there is no onFailure. While a frame is on the worker: waits
  // for it about a UI frame, then shows the last picture at this size instead (the moving view
  // is not drawn: the refinement after it draws the newest).
  void render(const Camera& camera, const RenderSettings& settings, int width, int height) override;
  void beginFrame(const Camera& camera, const RenderSettings& settings, int width,
                  int height) override;
  bool stepFrame(double budgetMs) override;
  // 0 until the worker's frame is there, then its wall time over the last worker frame's.
  double frameProgress() const override;
  Image8 readImage() const override { return image_; }
  unsigned outputTexture() const override { return texture_.id(); }
  RenderStats stats() const override { return stats_; }

 private:
  using Clock = std::chrono::steady_clock;
  // What the worker hands back: whether every rank drew the frame, and its picture.
  struct WorkerFrame {
    bool drawn = false;
    Image8 image;
    double wallMs = 0.0;
  };
  FrameDescription describe(const Camera& camera, const RenderSettings& settings, int width,
                            int height) const;
  void startWorker(const FrameDescription& frame);
  // Takes the worker's frame (waiting for it) and shows it where `show`, or where the texture
  // has its size (one a newer frame replaces); false when it failed.
  bool collectWorker(bool always);
  // After a failed frame: onFailure once, or throws.
  void failed(bool wasFailed);
  // Shows image_ through the texture and takes the frame's statistics from the link.
  void show(int width, int height, Clock::time_point start);
  // image_ (RGB, width x height) into the texture.
  void upload(int width, int height);

  std::shared_ptr<ClusterLink> link_;
  platform::GlContext* window_;
  std::function<void()> onFailure_;
  TransferFunction tf_;
  Image8 image_;
  gl::Texture texture_;
  RenderStats stats_;
  // Worker frames: on once setWorkerFrames ran and a synchronous frame was drawn.
  std::function<void()> releaseContext_;
  bool drawnOnce_ = false;
  std::future<WorkerFrame> worker_;
  int workerWidth_ = 0, workerHeight_ = 0;
  std::optional<FrameDescription> next_;  // the newest beginFrame's view while a frame is out
  bool synchronousFrame_ = false;         // the frame begun is the default's (render() in a step)
  bool frameShown_ = true;                // the newest beginFrame's frame is shown
  Clock::time_point begun_;               // the newest beginFrame
  Clock::time_point workerStart_;
  bool failedBeforeWorker_ = false;  // the link had failed before the worker's frame
  double workerMs_ = 0.0;            // the last worker frame's wall time
};

}  // namespace ewa::dist
