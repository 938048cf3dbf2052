// The window's frames drawn by every rank: ClusterLink (rank 0 sends each frame's description and
// draws it with the others), DistributedRenderer (the viewer's Renderer over it) and serveFrames
// (the other ranks' loop).
#pragma once

#include <mpi.h>

#include <functional>
#include <memory>
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
  // and composite times.
  std::vector<std::string> statisticsLines() const;
  // The slowest rank's render and composite milliseconds of the last frame.
  double slowestRenderMs() const;
  double slowestCompositeMs() const;

 private:
  DistributedSession& session_;
  bool failed_ = false, quitSent_ = false;
  int width_ = 0, height_ = 0;  // of the last frame
  double wallMs_ = 0.0;
};

// Ranks other than 0: receives frame descriptions and draws each with the others until a
// quit. Returns the quit's exit status, or 1 after a frame failed on some rank.
int serveFrames(DistributedSession& session);

// The viewer's renderer on rank 0: each render() is one collective frame through the link,
// finished on the CPU (finishPicture) and shown through a texture. Every level of detail draws
// the ranks' bricks at full resolution; only the image is smaller. setVolume is ignored: each
// rank holds its own brick.
class DistributedRenderer : public Renderer {
 public:
  // `window`: the context the output texture lives in, made current again after each frame
  // (this rank's brick is drawn on a headless context of its own); null: no texture, readImage
  // only. `onFailure`: called once when a frame failed on some rank (the window closes).
  DistributedRenderer(std::shared_ptr<ClusterLink> link, platform::GlContext* window,
                      std::function<void()> onFailure = {});

  void setVolume(const Volume& /*volume*/) override {}
  void setTransferFunction(const TransferFunction& tf) override { tf_ = tf; }
  // After a failed frame (and for every frame after it): calls onFailure once and keeps the
  // last picture, or throws where there is no onFailure.
  void render(const Camera& camera, const RenderSettings& settings, int width, int height) override;
  Image8 readImage() const override { return image_; }
  unsigned outputTexture() const override { return texture_.id(); }
  RenderStats stats() const override { return stats_; }

 private:
  std::shared_ptr<ClusterLink> link_;
  platform::GlContext* window_;
  std::function<void()> onFailure_;
  TransferFunction tf_;
  Image8 image_;
  gl::Texture texture_;
  RenderStats stats_;
};

}  // namespace ewa::dist
