// DistributedSession: open once (source, split, brick, agreed statistics), then collective frames.
#include "dist/mpi_session.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

#include "app/scene.h"
#include "core/stopwatch.h"
#include "core/volume_crop.h"
#include "dist/brick_clip.h"
#include "dist/brick_ghosts.h"
#include "dist/brick_weights.h"
#include "dist/icet_compositor.h"
#include "dist/mpi_brick_renderer.h"
#include "dist/mpi_collective.h"
#include "dist/mpi_ghost_exchange.h"
#include "dist/mpi_local_rank.h"
#include "dist/mpi_render.h"
#include "dist/visibility_order.h"
#include "platform/egl_device_choice.h"

namespace ewa::dist {

namespace {

using Clock = std::chrono::steady_clock;

// FNV-1a over bytes, folded into a double's exact integers so that MPI carries it as one.
struct Fingerprint {
  uint64_t h = 1469598103934665603ull;
  void add(const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  void add(double v) { add(&v, sizeof v); }
};

// What every rank must hold the same before the first frame: the whole volume's grid, value
// range and histogram (behind splat quantization and the default transfer function), the
// transfer function and the camera. They agree unless the ranks read different files.
uint64_t sceneFingerprint(const WholeGrid& g, const Volume& v, const TransferFunction& tf,
                          const Camera& camera) {
  Fingerprint f;
  for (int a = 0; a < 3; ++a) {
    f.add(double(g.dims[size_t(a)]));
    f.add(g.spacing[a]);
    f.add(g.origin[a]);
    f.add(camera.position[a]);
    f.add(camera.focalPoint[a]);
  }
  f.add(v.minValue());
  f.add(v.maxValue());
  f.add(v.histogram().data(), v.histogram().size() * sizeof(uint64_t));
  for (const glm::vec4& s : tf.bake(v.minValue(), v.maxValue(), 256)) f.add(&s, sizeof s);
  return f.h;
}

// The voxels of `brick` grown by `ghost` on each side, inside the whole volume.
VoxelRegion grownRegion(const VoxelBox& brick, const std::array<int64_t, 3>& ghost,
                        const std::array<int64_t, 3>& dims) {
  VoxelRegion region;
  for (size_t a = 0; a < 3; ++a) {
    region.lo[a] = std::max<int64_t>(brick.low[a] - ghost[a], 0);
    region.hi[a] = std::min<int64_t>(brick.high[a] + ghost[a], dims[a]);
  }
  return region;
}

// The line a rank says when its voxels do not fit in its memory (std::bad_alloc says nothing).
std::string outOfMemory(const VoxelRegion& r) {
  const int64_t voxels = (r.hi[0] - r.lo[0]) * (r.hi[1] - r.lo[1]) * (r.hi[2] - r.lo[2]);
  return "out of memory holding voxels [" + std::to_string(r.lo[0]) + "," +
         std::to_string(r.lo[1]) + "," + std::to_string(r.lo[2]) + "]-[" + std::to_string(r.hi[0]) +
         "," + std::to_string(r.hi[1]) + "," + std::to_string(r.hi[2]) + ") (" +
         std::to_string(voxels) +
         " voxels, its brick and ghosts): start more ranks, or give each more memory";
}

bool contains(const VoxelRegion& outer, const VoxelRegion& inner) {
  for (size_t a = 0; a < 3; ++a)
    if (inner.lo[a] < outer.lo[a] || inner.hi[a] > outer.hi[a]) return false;
  return true;
}

double peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

}  // namespace

DistributedSession::DistributedSession(const Options& options, MPI_Comm comm)
    : comm_(comm), backend_(options.backend), shaderDir_(options.shaderDir) {
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &size_);
  // Where a node has several GPUs, each rank draws on the one its node-local rank picks.
  platform::setEglLocalRank(nodeLocalRank(comm));
}

DistributedSession::~DistributedSession() = default;

std::unique_ptr<DistributedSession> DistributedSession::open(const Options& options,
                                                             MPI_Comm comm) {
  std::unique_ptr<DistributedSession> s(new DistributedSession(options, comm));
  // Every rank opens the source (metadata only where the format is read by parts; rank 0 alone
  // loads any other format) and frames the camera on the whole volume's bounds; a rank that
  // cannot (a file missing on its node) says so for all.
  s->source_ = BrickSource::open(options, comm);
  if (!s->source_) return nullptr;
  std::string error;
  try {
    const WholeGrid& g = s->source_->grid();
    s->initialCamera_ =
        initialCameraForBounds(g.worldBoundsMin(), g.worldBoundsMax(), g.patientFrame, options);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return nullptr;
  if (s->rank_ == 0 && !s->source_->note().empty())
    std::cerr << "ewaview-mpi: note: " << s->source_->note() << std::endl;

  // A first split by voxel count, and this rank's brick grown by the ghost voxels the first
  // frame reads: enough to agree on the statistics and the transfer function, which the split
  // by visible voxels needs.
  const WholeGrid& grid = s->grid();
  s->split_ = splitBricks(VoxelWeights(grid.dims), s->size_);
  s->brick_ = s->split_.bricks[size_t(s->rank_)];
  const GhostReach reach =
      frameGhostReach(grid, s->initialCamera_, options.render, options.width, options.height);
  s->ghost_ = ghostVoxels(reach, grid.spacing);
  const VoxelRegion region = grownRegion(s->brick_, s->ghost_, grid.dims);
  if (!s->readVoxels(!s->brick_.empty(), region)) return nullptr;
  const Volume& volume = s->volume_;

  // The whole volume's value range (every voxel lies in some rank's region) and histogram (of
  // each rank's own voxels, over that range), agreed on before anything is classified: splats
  // are quantized over the range, and the default transfer function comes from both.
  // A region without finite values has the range {0, 0}: it must not widen the whole's.
  bool finite = false;
  if (!s->brick_.empty())
    for (uint64_t count : volume.histogram()) finite = finite || count > 0;
  const double range[2] = {finite ? -volume.minValue() : -INFINITY,
                           finite ? volume.maxValue() : -INFINITY};
  double global[2];
  MPI_Allreduce(range, global, 2, MPI_DOUBLE, MPI_MAX, comm);
  s->lo_ = -global[0];
  s->hi_ = global[1];
  if (!(s->lo_ <= s->hi_)) s->lo_ = s->hi_ = 0.0;
  std::vector<uint64_t> histogram(size_t(Volume::histogramBins()), 0);
  if (!s->brick_.empty()) {
    std::array<int64_t, 3> low, high;
    for (size_t a = 0; a < 3; ++a) {
      low[a] = s->brick_.low[a] - region.lo[a];
      high[a] = s->brick_.high[a] - region.lo[a];
    }
    histogram = volume.histogramOf(low, high, s->lo_, s->hi_);
  }
  s->histogram_.assign(histogram.size(), 0);
  MPI_Allreduce(histogram.data(), s->histogram_.data(), int(histogram.size()), MPI_UINT64_T,
                MPI_SUM, comm);

  try {
    s->finishBrick();  // the statistics and data box of the volume just read
    s->transferFunction_ = sceneTransferFunction(options, s->source_->sidecar(),
                                                 s->source_->ownTransferFunction(), s->volume_);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return nullptr;

  // The ranks agree on the grid, the statistics, the transfer function and the camera.
  if (differsFromRank0(sceneFingerprint(grid, s->volume_, s->transferFunction_, s->initialCamera_),
                       "this rank read another volume, transfer function or camera than rank 0 "
                       "(are the files the same on every node?)",
                       comm))
    return nullptr;
  if (options.split == "visible" && s->size_ > 1 && !s->splitByVisibleVoxels(options))
    return nullptr;
  return s;
}

bool DistributedSession::splitByVisibleVoxels(const Options& options) {
  // Each rank counts its brick's voxels that become splats under the agreed transfer function
  // per block of the whole; the sum over the ranks, with every voxel's own smaller weight
  // (kHiddenVoxelWeight), weighs the split, so that ranks which drew empty space take more of the
  // visible part (VisIt #2596) and no brick of empty space outgrows a rank's memory. Where
  // nothing is visible it is the split by voxels.
  const WholeGrid& grid = this->grid();
  std::string error;
  std::vector<double> weights;
  try {
    VoxelBox empty;
    weights =
        visibleBlockWeights(volume_, region_.lo, brick_.empty() ? empty : brick_, grid.dims,
                            kVisibleBlock, transferFunction_, splatClassification(options.render));
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm_)) return false;
  MPI_Allreduce(MPI_IN_PLACE, weights.data(), int(weights.size()), MPI_DOUBLE, MPI_SUM, comm_);
  addVoxelWeights(weights, grid.dims, kVisibleBlock, kHiddenVoxelWeight);
  split_ = splitBricks(VoxelWeights(grid.dims, kVisibleBlock, weights), size_);
  const VoxelBox brick = split_.bricks[size_t(rank_)];
  const bool moved = !(brick == brick_);
  brick_ = brick;
  // A moved brick is read anew: the old one's voxels go first, so a rank never holds both.
  if (moved) volume_ = Volume();
  // Only the ranks whose brick moved read again (with the others where rank 0 sends them).
  if (!readVoxels(moved && !brick_.empty(), grownRegion(brick_, ghost_, grid.dims))) return false;
  if (moved) {
    try {
      finishBrick();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  return !anyFailed(error, comm_);
}

bool DistributedSession::readVoxels(bool read, const VoxelRegion& region) {
  // A scattered source sends the regions from rank 0, a chunked one trades the ghosts: every
  // rank takes part when any reads.
  const bool chunked = source_->chunked();
  int any = read ? 1 : 0;
  if (chunked || source_->scattered())
    MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_LOR, comm_);
  if (!any) return true;
  std::string error;
  const auto attempt = [&](const std::function<void()>& step) {
    try {
      step();
    } catch (const std::bad_alloc&) {
      error = outOfMemory(region);
    } catch (const std::exception& e) {
      error = e.what();
    }
  };
  Volume v;
  if (chunked) {
    // Each rank reads its brick alone (or cuts it from what it holds) and the ghosts come from
    // the ranks owning them; a rank that keeps what it holds names its brick alone as its region
    // (it takes nothing, and gives its brick's voxels to the others' regions).
    const VoxelRegion brick = grownRegion(brick_, {0, 0, 0}, grid().dims);
    const VoxelRegion wanted = read ? region : brick;
    std::vector<int64_t> all(size_t(size_) * 6);
    const int64_t mine[6] = {wanted.lo[0], wanted.lo[1], wanted.lo[2],
                             wanted.hi[0], wanted.hi[1], wanted.hi[2]};
    MPI_Allgather(mine, 6, MPI_INT64_T, all.data(), 6, MPI_INT64_T, comm_);
    std::vector<VoxelRegion> regions(static_cast<size_t>(size_));
    for (size_t r = 0; r < regions.size(); ++r)
      for (size_t a = 0; a < 3; ++a) {
        regions[r].lo[a] = all[r * 6 + a];
        regions[r].hi[a] = all[r * 6 + 3 + a];
      }
    Volume own;
    attempt([&] {
      if (brick_.empty()) return;
      if (volume_.empty() || !contains(region_, brick)) {
        own = source_->read(brick);
        return;
      }
      VoxelRange range;
      for (size_t a = 0; a < 3; ++a) {
        range.low[a] = brick.lo[a] - region_.lo[a];
        range.high[a] = brick.hi[a] - region_.lo[a] - 1;
      }
      own = cropVolume(volume_, range);
    });
    if (anyFailed(error, comm_)) return false;
    attempt([&] { v = exchangeGhosts(own, split_.bricks, regions, comm_); });
  } else {
    attempt([&] { v = source_->readShared(read ? region : VoxelRegion{}, comm_); });
  }
  if (read && error.empty()) {
    volume_ = std::move(v);
    region_ = region;
  }
  return !anyFailed(error, comm_);
}

void DistributedSession::finishBrick() {
  const VoxelRegion& region = region_;
  if (brick_.empty()) {
    // Nothing to draw; the statistics still make the transfer function every rank agrees on.
    volume_ = Volume({1, 1, 1}, grid().spacing, grid().origin, ScalarType::UInt8, {0});
  }
  voxelsRead_ = brick_.empty() ? 0 : (long long)volume_.voxelCount();
  // The brick as a volume of its own that draws as its part of the whole: the whole's value
  // statistics and data box (in the brick's indices), and its inner faces cut exactly.
  volume_.setValueStatistics(lo_, hi_, histogram_);
  DataBox box = grid().indexDataBox();
  for (int a = 0; a < 3; ++a) {
    box.low[a] -= double(region.lo[size_t(a)]);
    box.high[a] -= double(region.lo[size_t(a)]);
    localBrick_.low[size_t(a)] = brick_.low[size_t(a)] - region.lo[size_t(a)];
    localBrick_.high[size_t(a)] = brick_.high[size_t(a)] - region.lo[size_t(a)];
  }
  volume_.setIndexDataBox(box);
  volumeChanged_ = true;
}

bool DistributedSession::render(const Camera& camera, const RenderSettings& settings,
                                const TransferFunction& tf, int w, int h,
                                std::vector<float>* whole) {
  // This rank's own work (reading, classifying, drawing), not its waits for the others.
  double renderMs = 0.0;
  auto start = Clock::now();
  std::string error;
  // The ghosts this frame's kernels need; more than held: the brick is read again.
  ghost_ = ghostVoxels(frameGhostReach(grid(), camera, settings, w, h), grid().spacing);
  const VoxelRegion needed = grownRegion(brick_, ghost_, grid().dims);
  const bool grow = !brick_.empty() && !contains(region_, needed);
  if (!readVoxels(grow, needed)) return false;
  try {
    if (grow) finishBrick();
  } catch (const std::exception& e) {
    error = e.what();
  }
  renderMs += millisecondsSince(start);
  if (anyFailed(error, comm_)) return false;

  // One slab grid for all: each rank finds the nearest kernel among its own brick's splats
  // (classified again when the volume, transfer function or classification changed); the least
  // over the ranks is where the whole volume's partition starts its grid (its nearest kernel),
  // so every brick cuts the one-process picture's slabs.
  const Classification classification = splatClassification(settings);
  ClassifiedSplats splats;
  bool fresh = false;
  double front = INFINITY;
  start = Clock::now();
  try {
    if (!brick_.empty()) {
      if (!renderer_) renderer_ = std::make_unique<BrickRenderer>(backend_, shaderDir_);
      fresh = volumeChanged_ || !(tf == classifiedTf_) || !(classification == classified_);
      if (fresh) {
        if (volumeChanged_) renderer_->setVolume(volume_);
        splats = classifySplats(volume_, tf, classification);
        front = brickKernelFront(volume_, localBrick_, splats, camera, settings, w, h);
        volumeChanged_ = false;
        classifiedTf_ = tf;
        classified_ = classification;
      } else {
        const SplatRenderer& r = renderer_->splatRenderer();
        front = brickKernelFront(volume_, localBrick_, r.splats(), r.attributes(), camera, settings,
                                 w, h);
      }
    }
  } catch (const std::exception& e) {
    error = e.what();
  }
  renderMs += millisecondsSince(start);
  if (anyFailed(error, comm_)) return false;
  double anchor = INFINITY;
  MPI_Allreduce(&front, &anchor, 1, MPI_DOUBLE, MPI_MIN, comm_);
  // Nothing visible anywhere: any shared grid will do.
  if (!std::isfinite(anchor)) anchor = cornerSlabAnchor(volume_, camera, settings, w, h);

  // This rank's picture: premultiplied RGBA floats (composite), the optical depth (X-ray) or
  // the maximum (MIP); nothing where the brick is empty.
  std::vector<float> picture(size_t(w) * size_t(h) * 4, 0.0f);
  std::string note;
  start = Clock::now();
  try {
    if (!brick_.empty()) {
      RenderSettings cut = settings;
      if (const std::string problem = addBrickPlanes(volume_, localBrick_, &cut.clip);
          !problem.empty())
        throw std::runtime_error(problem);
      // X-ray and MIP draw one slab of unbounded thickness: no grid to share.
      const double a = settings.mode == RenderMode::Composite ? anchor : NAN;
      picture = renderer_->render(tf, camera, cut, w, h, a, fresh ? &splats : nullptr);
      note = renderer_->note();
      if (picture.size() != size_t(w) * size_t(h) * 4)
        throw std::runtime_error("the renderer returned no picture");
    }
  } catch (const std::exception& e) {
    error = e.what();
  }
  renderMs += millisecondsSince(start);
  if (anyFailed(error, comm_)) return false;

  // Composite: blended in visibility order, or summed (X-ray) or maximal (MIP) per pixel.
  const auto compositeStart = Clock::now();
  double bytesSent = 0.0;
  try {
    const IndexView view = indexView(camera, grid().origin, grid().direction, grid().spacing);
    if (settings.mode == RenderMode::Composite) {
      if (!compositor_) compositor_ = std::make_unique<IceTCompositor>(comm_);
      *whole = compositor_->blend(picture, w, h, visibilityOrder(split_, view));
      bytesSent = double(compositor_->lastBytesSent());
    } else {
      int64_t bytes = 0;
      *whole = settings.mode == RenderMode::XRay ? reduceSum(picture, comm_, 0, &bytes)
                                                 : reduceMax(picture, comm_, 0, &bytes);
      bytesSent = double(bytes);
    }
  } catch (const std::exception& e) {
    abortAll(e.what(), comm_);
  }
  const double compositeMs = millisecondsSince(compositeStart);

  // Each rank's figures and whether it has a note, on rank 0.
  static_assert(sizeof(RankFigures) % sizeof(double) == 0, "RankFigures: doubles only");
  RankFigures ours{renderMs, compositeMs, double(voxelsRead_), peakRssMb(), bytesSent};
  if (renderer_ && !brick_.empty()) {
    const RenderStats& r = renderer_->stats();
    ours.splats = double(r.splatsTotal);
    ours.splatsDrawn = double(r.splatsDrawn);
    ours.slabEntries = double(r.slabEntries);
    ours.slabs = double(r.slabs);
    ours.cpu = r.cpu ? 1.0 : 0.0;
  }
  constexpr int kFields = int(sizeof(RankFigures) / sizeof(double));
  figures_.assign(rank_ == 0 ? size_t(size_) : 0, RankFigures{});
  MPI_Gather(&ours, kFields, MPI_DOUBLE, figures_.data(), kFields, MPI_DOUBLE, 0, comm_);
  // The renderer's note is the same on every rank that draws; rank 0 may draw nothing.
  int length = int(note.size()), longest = 0;
  MPI_Allreduce(&length, &longest, 1, MPI_INT, MPI_MAX, comm_);
  int owner = length == longest ? rank_ : size_, first = 0;
  MPI_Allreduce(&owner, &first, 1, MPI_INT, MPI_MIN, comm_);
  note.resize(size_t(longest));
  MPI_Bcast(note.data(), longest, MPI_CHAR, first, comm_);
  note_ = rank_ == 0 ? note : std::string();
  return true;
}

double DistributedSession::slowest(double RankFigures::*figure) const {
  double ms = 0.0;
  for (const RankFigures& f : figures_) ms = std::max(ms, f.*figure);
  return ms;
}

}  // namespace ewa::dist
