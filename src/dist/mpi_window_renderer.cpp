// ClusterLink, serveFrames and DistributedRenderer: each window frame as a description
// broadcast from rank 0, drawn by every rank and composited onto rank 0.
#include "dist/mpi_window_renderer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "core/stopwatch.h"
#include "dist/mpi_collective.h"
#include "dist/mpi_render.h"
#include "dist/mpi_session.h"
#include "gl/gl_api.h"

namespace ewa::dist {

namespace {

using Clock = std::chrono::steady_clock;

// Rank 0's bytes to every rank: their size, then the bytes (each rank sizes its buffer first).
void broadcastBytes(std::vector<uint8_t>* bytes, MPI_Comm comm) {
  uint64_t size = bytes->size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, comm);
  bytes->resize(size_t(size));
  MPI_Bcast(bytes->data(), int(size), MPI_BYTE, 0, comm);
}

// How long a moving frame waits for a full-quality frame under way before the window shows the
// last picture instead: about a UI frame.
constexpr std::chrono::milliseconds kRenderWait{20};

// `image` (RGB, top row first) at width x height, nearest pixels: the last picture standing in
// for a view not drawn.
Image8 resized(const Image8& image, int width, int height) {
  Image8 out;
  out.width = width;
  out.height = height;
  out.channels = image.channels;
  const size_t c = size_t(image.channels);
  out.pixels.resize(size_t(width) * size_t(height) * c);
  for (int y = 0; y < height; ++y) {
    const size_t sy =
        std::min(size_t(image.height - 1), size_t(y) * size_t(image.height) / size_t(height));
    for (int x = 0; x < width; ++x) {
      const size_t sx =
          std::min(size_t(image.width - 1), size_t(x) * size_t(image.width) / size_t(width));
      const uint8_t* in = image.pixels.data() + (sy * size_t(image.width) + sx) * c;
      std::copy(in, in + c, out.pixels.data() + (size_t(y) * size_t(width) + size_t(x)) * c);
    }
  }
  return out;
}

// The panel shows this many ranks' lines at most, so that it stays on screen.
constexpr size_t kMaxRankLines = 8;

}  // namespace

ClusterLink::ClusterLink(DistributedSession& session) : session_(session) {}

bool ClusterLink::draw(const FrameDescription& frame, std::vector<float>* picture) {
  if (failed_ || quitSent_) return false;
  std::vector<uint8_t> bytes = serializeFrame(frame);
  const Clock::time_point start = Clock::now();
  broadcastBytes(&bytes, session_.comm());
  if (!session_.render(frame.camera, frame.settings, frame.tf, frame.width, frame.height,
                       picture)) {
    failed_ = true;
    return false;
  }
  std::vector<std::string> lines = makeLines(frame.width, frame.height, millisecondsSince(start));
  const std::lock_guard<std::mutex> lock(linesMutex_);
  lines_ = std::move(lines);
  return true;
}

void ClusterLink::quit(int status) {
  if (failed_ || quitSent_) return;
  quitSent_ = true;
  FrameDescription frame;
  frame.quit = true;
  frame.exitStatus = status;
  std::vector<uint8_t> bytes = serializeFrame(frame);
  broadcastBytes(&bytes, session_.comm());
}

std::vector<std::string> ClusterLink::statisticsLines() const {
  const std::lock_guard<std::mutex> lock(linesMutex_);
  return lines_;
}

std::vector<std::string> ClusterLink::makeLines(int width, int height, double wallMs) const {
  const std::vector<RankFigures>& figures = session_.figures();
  std::vector<std::string> lines;
  if (figures.empty()) return lines;
  char text[160];
  const std::array<int64_t, 3>& g = session_.ghost();
  std::snprintf(text, sizeof text, "%d ranks, %d x %d: %.0f ms, ghosts %lld %lld %lld",
                session_.size(), width, height, wallMs, (long long)g[0], (long long)g[1],
                (long long)g[2]);
  lines.emplace_back(text);
  for (size_t r = 0; r < figures.size() && r < kMaxRankLines; ++r) {
    const VoxelBox& b = session_.split().bricks[r];
    std::snprintf(text, sizeof text,
                  "rank %zu [%lld %lld %lld]-[%lld %lld %lld]: render %.1f, "
                  "composite %.1f ms",
                  r, (long long)b.low[0], (long long)b.low[1], (long long)b.low[2],
                  (long long)b.high[0], (long long)b.high[1], (long long)b.high[2],
                  figures[r].renderMs, figures[r].compositeMs);
    lines.emplace_back(text);
  }
  if (figures.size() > kMaxRankLines)
    lines.push_back("... and " + std::to_string(figures.size() - kMaxRankLines) + " more ranks");
  return lines;
}

int serveFrames(DistributedSession& session) {
  std::vector<float> none;
  for (;;) {
    std::vector<uint8_t> bytes;
    broadcastBytes(&bytes, session.comm());
    FrameDescription frame;
    try {
      frame = deserializeFrame(bytes.data(), bytes.size());
    } catch (const std::exception& e) {
      abortAll(e.what(), session.comm());  // rank 0 waits in the frame: no way to agree
    }
    if (frame.quit) return frame.exitStatus;
    if (!session.render(frame.camera, frame.settings, frame.tf, frame.width, frame.height, &none))
      return 1;
  }
}

DistributedRenderer::DistributedRenderer(std::shared_ptr<ClusterLink> link,
                                         platform::GlContext* window,
                                         std::function<void()> onFailure)
    : link_(std::move(link)), window_(window), onFailure_(std::move(onFailure)) {}

DistributedRenderer::~DistributedRenderer() {
  // The ranks are in the frame: it ends before anything else is sent (the quit).
  if (worker_.valid()) worker_.wait();
}

void DistributedRenderer::setWorkerFrames(std::function<void()> releaseContext) {
  releaseContext_ = std::move(releaseContext);
}

FrameDescription DistributedRenderer::describe(const Camera& camera, const RenderSettings& settings,
                                               int width, int height) const {
  FrameDescription frame;
  frame.camera = camera;
  frame.settings = settings;
  frame.tf = tf_;
  frame.width = width;
  frame.height = height;
  return frame;
}

void DistributedRenderer::failed(bool wasFailed) {
  // The failing rank said why in one line; the window closes with the last picture on it
  // rather than adding a line of its own.
  if (onFailure_) {
    if (!wasFailed) onFailure_();
    return;
  }
  throw std::runtime_error("the ranks stopped after a failed frame");
}

void DistributedRenderer::render(const Camera& camera, const RenderSettings& settings, int width,
                                 int height) {
  const Clock::time_point start = Clock::now();
  // A whole frame replaces the full-quality view asked meanwhile (never sent now).
  next_.reset();
  synchronousFrame_ = false;
  frameShown_ = true;
  if (worker_.valid()) {
    // MPI one thread at a time: this frame would wait for the ranks' frame under way. The
    // window answers instead, showing the last picture at this size; the refinement that
    // follows a moving view draws the newest one.
    if (!image_.pixels.empty() &&
        worker_.wait_until(start + kRenderWait) != std::future_status::ready) {
      // The statistics stay the last frame's: the worker writes the ranks' figures now.
      if (image_.width != width || image_.height != height) {
        image_ = resized(image_, width, height);
        upload(width, height);
      }
      return;
    }
    if (!collectWorker(false)) return;
  }
  const FrameDescription frame = describe(camera, settings, width, height);
  std::vector<float> picture;
  const bool wasFailed = link_->failed();
  const bool drawn = link_->draw(frame, &picture);
  // This rank's brick was drawn on its headless context (its GL functions loaded): the
  // window's context and functions again.
  if (window_) window_->makeCurrent();
  if (!drawn) return failed(wasFailed);
  drawnOnce_ = true;
  image_ = finishPicture(picture, width, height, settings);
  show(width, height, start);
}

void DistributedRenderer::beginFrame(const Camera& camera, const RenderSettings& settings,
                                     int width, int height) {
  // The first frames make this rank's brick renderer and its hidden window, on this thread.
  synchronousFrame_ = !releaseContext_ || !window_ || (!drawnOnce_ && !worker_.valid());
  if (synchronousFrame_) return Renderer::beginFrame(camera, settings, width, height);
  begun_ = Clock::now();
  frameShown_ = false;
  const FrameDescription frame = describe(camera, settings, width, height);
  if (worker_.valid())
    next_ = frame;  // replaces an older one: the views passed through are never sent
  else
    startWorker(frame);
}

void DistributedRenderer::startWorker(const FrameDescription& frame) {
  workerWidth_ = frame.width;
  workerHeight_ = frame.height;
  workerStart_ = Clock::now();
  // Read here: the worker's frame sets it.
  failedBeforeWorker_ = link_->failed();
  worker_ = std::async(std::launch::async, [link = link_, frame, release = releaseContext_] {
    WorkerFrame done;
    const Clock::time_point start = Clock::now();
    std::vector<float> picture;
    try {
      done.drawn = link->draw(frame, &picture);
    } catch (...) {
      release();
      throw;
    }
    // The brick's context is bound here by its frame: unbound, so a synchronous frame on the
    // window's thread may bind it.
    release();
    if (done.drawn) done.image = finishPicture(picture, frame.width, frame.height, frame.settings);
    done.wallMs = millisecondsSince(start);
    return done;
  });
}

bool DistributedRenderer::collectWorker(bool always) {
  WorkerFrame done = worker_.get();  // rethrows what the worker threw
  worker_ = {};
  // The worker's frame loaded the process-wide GL functions from the brick's context: the
  // window's again (the same GL library, so the pointers this thread used meanwhile held). The
  // worker writes them while this thread may call through them: a race in form only, as every
  // value written is the one already there; per-context function tables would remove it.
  if (window_) window_->makeCurrent();
  if (!done.drawn) {
    next_.reset();
    failed(failedBeforeWorker_);
    return false;
  }
  workerMs_ = done.wallMs;
  // A frame another replaces is shown only where the window shows the texture at its size (a
  // moving level's smaller picture is on screen now: the picture waits for the next one).
  if (!always && (texture_.width() != workerWidth_ || texture_.height() != workerHeight_))
    return true;
  image_ = std::move(done.image);
  show(workerWidth_, workerHeight_, workerStart_);
  return true;
}

bool DistributedRenderer::stepFrame(double budgetMs) {
  if (synchronousFrame_) {
    synchronousFrame_ = false;
    return Renderer::stepFrame(budgetMs);
  }
  const Clock::time_point deadline =
      Clock::now() + std::chrono::microseconds(int64_t(std::max(0.0, budgetMs) * 1000.0));
  while (worker_.valid()) {
    if (worker_.wait_until(deadline) != std::future_status::ready) return false;
    // The frame the newest beginFrame asked for, or one it replaced.
    if (!collectWorker(!next_)) return frameShown_ = true;  // failed: the window closes
    if (!next_) {
      frameShown_ = true;
      stats_.renderMs = millisecondsSince(begun_);
      return true;
    }
    // Shown a frame older than the newest asked: that one now.
    startWorker(*next_);
    next_.reset();
  }
  return frameShown_;
}

double DistributedRenderer::frameProgress() const {
  if (synchronousFrame_) return Renderer::frameProgress();
  if (frameShown_) return 1.0;
  if (workerMs_ <= 0.0 || next_) return 0.0;
  return std::min(0.99, millisecondsSince(workerStart_) / workerMs_);
}

void DistributedRenderer::upload(int width, int height) {
  if (!window_) return;
  if (texture_.width() != width || texture_.height() != height)
    texture_ = gl::Texture::create2D(GL_RGBA8, width, height);
  // The texture's rows bottom first, as the renderers' output textures are.
  std::vector<uint8_t> rgba(size_t(width) * size_t(height) * 4);
  for (int y = 0; y < height; ++y) {
    const uint8_t* in = image_.pixels.data() + size_t(height - 1 - y) * size_t(width) * 3;
    uint8_t* out = rgba.data() + size_t(y) * size_t(width) * 4;
    for (int x = 0; x < width; ++x) {
      out[4 * x] = in[3 * x];
      out[4 * x + 1] = in[3 * x + 1];
      out[4 * x + 2] = in[3 * x + 2];
      out[4 * x + 3] = 255;
    }
  }
  texture_.subImage2D(0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
}

void DistributedRenderer::show(int width, int height, Clock::time_point start) {
  upload(width, height);
  stats_ = RenderStats{};
  stats_.note = link_->session().note();
  // The stage lines of the panel: the slowest rank's brick (classification included) and the
  // slowest rank's part of the composite; the ranks' own lines follow them.
  stats_.splatMs = link_->session().slowestRenderMs();
  stats_.compositeMs = link_->session().slowestCompositeMs();
  // The whole volume's splats are the bricks' together; the slabs are one grid for all.
  for (const RankFigures& f : link_->session().figures()) {
    stats_.splatsTotal += size_t(f.splats);
    stats_.splatsDrawn += size_t(f.splatsDrawn);
    stats_.slabEntries += size_t(f.slabEntries);
    stats_.slabs = std::max(stats_.slabs, size_t(f.slabs));
    stats_.cpu = stats_.cpu || f.cpu > 0.0;
  }
  stats_.renderMs = millisecondsSince(start);
}

}  // namespace ewa::dist
