// renderDistributed: load and agree, split, render the brick, composite, write on rank 0.
#include "dist/mpi_render.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "app/headless.h"
#include "app/one_line.h"
#include "app/scene.h"
#include "core/orientation_axes.h"
#include "core/volume_orientation.h"
#include "dist/brick_clip.h"
#include "dist/brick_ghosts.h"
#include "dist/brick_split.h"
#include "dist/icet_compositor.h"
#include "dist/mpi_brick_source.h"
#include "dist/visibility_order.h"
#include "gl/shader_library.h"
#include "io/png_io.h"
#include "platform/gl_context.h"
#include "platform/headless_context.h"
#include "render/renderer_factory.h"
#include "render/splat_renderer.h"

namespace ewa::dist {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Whether any rank failed (`error` non-empty there); the lowest such rank prints its line.
bool anyFailed(const std::string& error, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int mine = error.empty() ? INT_MAX : rank;
  int first = INT_MAX;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == INT_MAX) return false;
  if (rank == first)
    std::cerr << "ewaview-mpi: rank " << rank << " of " << size << ": " << oneLine(error)
              << std::endl;
  return true;
}

// An error where the ranks cannot meet again (one may wait in a collective): one line, then
// every rank ends.
[[noreturn]] void abortAll(const std::string& error, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::cerr << "ewaview-mpi: rank " << rank << " of " << size << ": " << oneLine(error)
            << std::endl;
  MPI_Abort(comm, 1);
  std::abort();  // MPI_Abort does not return
}

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
uint64_t sceneFingerprint(const WholeGrid& g, const Scene& scene, const Camera& camera) {
  Fingerprint f;
  const Volume& v = scene.volume;
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
  for (const glm::vec4& s : scene.transferFunction.bake(v.minValue(), v.maxValue(), 256))
    f.add(&s, sizeof s);
  return f.h;
}

// The camera in the frame where voxel (i,j,k) sits at origin + (i,j,k) * spacing
// (cameraInVolumeFrame for the whole grid).
Camera cameraInGridFrame(const Camera& world, const WholeGrid& g) {
  if (g.direction == glm::dmat3(1.0)) return world;
  const glm::dmat3 inverse = glm::transpose(g.direction);
  Camera c = world;
  c.position = g.origin + inverse * (world.position - g.origin);
  c.focalPoint = g.origin + inverse * (world.focalPoint - g.origin);
  c.viewUp = inverse * world.viewUp;
  return c;
}

// The partition's view of the kernels in `camera`'s frame (as SplatRenderer's frame sets it).
DepthExtent depthExtent(const Volume& volume, const Camera& camera, const RenderSettings& settings,
                        int width, int height) {
  DepthExtent extent;
  extent.reach = kernelReach(camera.projection(width, height), settings.filter, settings.cutoff,
                             volume.spacing(), settings.kernelWidth, settings.depthCutoff);
  extent.rotation = camera.rotation();
  extent.spacing = volume.spacing();
  extent.kernelWidth = settings.kernelWidth;
  return extent;
}

}  // namespace

GhostReach frameGhostReach(const WholeGrid& g, const Camera& world, const RenderSettings& settings,
                           int width, int height) {
  const Camera camera = cameraInGridFrame(world, g);
  GhostReach ghost;
  ghost.reach = kernelReach(camera.projection(width, height), settings.filter, settings.cutoff,
                            g.spacing, settings.kernelWidth, settings.depthCutoff);
  ghost.farDepth = farthestDepth(g.indexDataBox(), g.origin, g.spacing, camera.viewMatrix());
  ghost.classification = splatClassification(settings);
  return ghost;
}

double cornerSlabAnchor(const Volume& volume, const Camera& world, const RenderSettings& settings,
                        int width, int height) {
  const Camera camera = cameraInVolumeFrame(world, volume);
  return slabAnchorDepth(volume.indexDataBox(), volume.origin(), camera.viewMatrix(),
                         depthExtent(volume, camera, settings, width, height));
}

double brickKernelFront(const Volume& volume, const VoxelBox& brick, const ClassifiedSplats& splats,
                        const Camera& world, const RenderSettings& settings, int width,
                        int height) {
  const Camera camera = cameraInVolumeFrame(world, volume);
  const SplatSet& set = splats.splats;
  return nearestKernelFront(set, splats.attributes, volume.origin(), camera.viewMatrix(),
                            footprintParams(settings, volume.spacing()).cullDepth,
                            depthExtent(volume, camera, settings, width, height), [&](size_t m) {
                              const PackedSplat& p = set.splats()[m];
                              const int64_t i = SplatSet::i(p), j = SplatSet::j(p),
                                            k = SplatSet::k(p);
                              return i >= brick.low[0] && i < brick.high[0] && j >= brick.low[1] &&
                                     j < brick.high[1] && k >= brick.low[2] && k < brick.high[2];
                            });
}

namespace {

// The splat renderer of this rank on its own headless context.
class BrickRenderer {
 public:
  BrickRenderer(const std::string& backend, const std::string& shaderDir)
      : context_(platform::createHeadlessContext(platform::parseHeadlessBackend(backend))),
        shaders_(shaderDir) {
    context_->makeCurrent();
    renderer_ = createRenderer(RendererKind::Splat, shaders_);
    splat_ = dynamic_cast<SplatRenderer*>(renderer_.get());
    if (!splat_) throw std::runtime_error("the splat renderer is not available");
  }
  ~BrickRenderer() {
    context_->makeCurrent();
    renderer_.reset();
  }
  std::vector<float> render(const Volume& volume, const TransferFunction& tf, const Camera& camera,
                            const RenderSettings& settings, int width, int height,
                            double slabAnchor, ClassifiedSplats* splats) {
    context_->makeCurrent();
    splat_->setSlabAnchor(slabAnchor);
    renderer_->setVolume(volume);
    renderer_->setTransferFunction(tf);
    // Splats classified already (to find the brick's nearest kernel) are not classified again.
    // As the renderer's own classification does: the transfer table first, then the splats.
    if (splats) {
      splat_->updateTransferTexture(tf);
      splat_->setSplats(std::move(*splats), splatClassification(settings));
    }
    renderer_->render(camera, settings, width, height);
    note_ = renderer_->stats().note;
    return splat_->readFramePicture();
  }
  const std::string& note() const { return note_; }

 private:
  std::unique_ptr<platform::GlContext> context_;
  gl::ShaderLibrary shaders_;
  std::unique_ptr<Renderer> renderer_;
  SplatRenderer* splat_ = nullptr;
  std::string note_;
};

uint8_t toByte(double v) {
  return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

}  // namespace

std::string distributedUsageProblem(const Options& o) {
  if (o.output.empty()) return "--output FILE.png is needed: ewaview-mpi renders headless";
  if (o.turntable > 0 || o.tour > 0) return "--turntable and --tour are not distributed yet";
  if (o.info || o.pick || !o.saveVolume.empty())
    return "--info, --pick and --save-volume need no ranks: use ewaview";
  if (o.overlay) return "--channel all (or a list) is not distributed yet: give one channel";
  if (o.render.renderer != RendererKind::Splat)
    return "only the splat renderer is distributed (--renderer splat)";
  return "";
}

Image8 finishPicture(const std::vector<float>& picture, int width, int height,
                     const RenderSettings& s) {
  Image8 image;
  image.width = width;
  image.height = height;
  image.channels = 3;
  image.pixels.resize(size_t(width) * size_t(height) * 3);
  const glm::dvec3 bg = s.background;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* v = picture.data() + (size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4;
      glm::dvec3 rgb;
      if (s.mode == RenderMode::XRay) {
        const double sum = double(std::max(v[3], 0.0f) * float(s.xrayScale));
        rgb = glm::dvec3(s.xrayMap == XRayMap::Attenuation ? std::exp(-sum) : sum);
      } else if (s.mode == RenderMode::Mip) {
        rgb = v[0] > 0.0f ? glm::dvec3(v[0]) : bg;
      } else {
        rgb = glm::dvec3(v[0], v[1], v[2]) + (1.0 - double(v[3])) * bg;
      }
      uint8_t* out = image.pixels.data() + (size_t(y) * size_t(width) + size_t(x)) * 3;
      for (int c = 0; c < 3; ++c) out[c] = toByte(rgb[c]);
    }
  return image;
}

std::vector<float> renderBrick(const Volume& volume, const VoxelBox& brick,
                               const TransferFunction& tf, const Camera& camera,
                               RenderSettings settings, int width, int height, double slabAnchor,
                               const std::string& backend, const std::string& shaderDir,
                               ClassifiedSplats* splats, std::string* note, double* ms) {
  if (const std::string problem = addBrickPlanes(volume, brick, &settings.clip); !problem.empty())
    throw std::runtime_error(problem);
  BrickRenderer renderer(backend, shaderDir);
  const auto start = Clock::now();
  // X-ray and MIP draw one slab of unbounded thickness: no grid to share.
  const double anchor = settings.mode == RenderMode::Composite ? slabAnchor : NAN;
  std::vector<float> picture =
      renderer.render(volume, tf, camera, settings, width, height, anchor, splats);
  if (ms) *ms = msSince(start);
  if (note) *note = renderer.note();
  if (picture.size() != size_t(width) * size_t(height) * 4)
    throw std::runtime_error("the renderer returned no picture");
  return picture;
}

int renderDistributed(const Options& options, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);

  // Every rank opens the source (metadata only where the format is read by parts) and frames
  // the camera on the whole volume's bounds; a rank that cannot (a file missing there) says so
  // for all.
  std::unique_ptr<BrickSource> source;
  Camera camera;
  std::string error;
  try {
    source = BrickSource::open(options);
    const WholeGrid& g = source->grid();
    camera =
        initialCameraForBounds(g.worldBoundsMin(), g.worldBoundsMax(), g.patientFrame, options);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return 1;
  if (rank == 0 && !source->note().empty())
    std::cerr << "ewaview-mpi: note: " << source->note() << std::endl;

  // The split, and this rank's brick grown by the ghost voxels its frame reads.
  const WholeGrid& grid = source->grid();
  const BrickSplit split = splitBricks(VoxelWeights(grid.dims), size);
  const VoxelBox& brick = split.bricks[size_t(rank)];
  RenderSettings settings = options.render;
  const int w = options.width, h = options.height;
  const GhostReach reach = frameGhostReach(grid, camera, settings, w, h);
  const std::array<int64_t, 3> ghost = ghostVoxels(reach, grid.spacing);
  VoxelRegion region;
  for (size_t a = 0; a < 3; ++a) {
    region.lo[a] = std::max<int64_t>(brick.low[a] - ghost[a], 0);
    region.hi[a] = std::min<int64_t>(brick.high[a] + ghost[a], grid.dims[a]);
  }

  // This rank's voxels.
  Volume volume;
  try {
    if (!brick.empty()) volume = source->read(region);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return 1;
  const long long voxelsRead = brick.empty() ? 0 : (long long)volume.voxelCount();

  // The whole volume's value range (every voxel lies in some rank's region) and histogram (of
  // each rank's own voxels, over that range), agreed on before anything is classified: splats
  // are quantized over the range, and the default transfer function comes from both.
  // A region without finite values has the range {0, 0}: it must not widen the whole's.
  bool finite = false;
  if (!brick.empty())
    for (uint64_t count : volume.histogram()) finite = finite || count > 0;
  const double range[2] = {finite ? -volume.minValue() : -INFINITY,
                           finite ? volume.maxValue() : -INFINITY};
  double global[2];
  MPI_Allreduce(range, global, 2, MPI_DOUBLE, MPI_MAX, comm);
  double lo = -global[0], hi = global[1];
  if (!(lo <= hi)) lo = hi = 0.0;
  std::vector<uint64_t> histogram(size_t(Volume::histogramBins()), 0);
  if (!brick.empty()) {
    std::array<int64_t, 3> low, high;
    for (size_t a = 0; a < 3; ++a) {
      low[a] = brick.low[a] - region.lo[a];
      high[a] = brick.high[a] - region.lo[a];
    }
    histogram = volume.histogramOf(low, high, lo, hi);
  }
  std::vector<uint64_t> wholeHistogram(histogram.size(), 0);
  MPI_Allreduce(histogram.data(), wholeHistogram.data(), int(histogram.size()), MPI_UINT64_T,
                MPI_SUM, comm);

  // The brick as a volume of its own that draws as its part of the whole: the whole's value
  // statistics and data box (in the brick's indices), and its inner faces cut exactly.
  Scene scene;
  VoxelBox localBrick;
  try {
    if (brick.empty()) {
      // Nothing to draw; the statistics still make the transfer function every rank agrees on.
      volume = Volume({1, 1, 1}, grid.spacing, grid.origin, ScalarType::UInt8, {0});
    }
    volume.setValueStatistics(lo, hi, wholeHistogram);
    DataBox box = grid.indexDataBox();
    for (int a = 0; a < 3; ++a) {
      box.low[a] -= double(region.lo[size_t(a)]);
      box.high[a] -= double(region.lo[size_t(a)]);
      localBrick.low[size_t(a)] = brick.low[size_t(a)] - region.lo[size_t(a)];
      localBrick.high[size_t(a)] = brick.high[size_t(a)] - region.lo[size_t(a)];
    }
    volume.setIndexDataBox(box);
    scene.transferFunction =
        sceneTransferFunction(options, source->sidecar(), source->ownTransferFunction(), volume);
    scene.name = source->name();
    scene.volume = std::move(volume);
    if (rank == 0) refuseToOverwriteInputs(options.output, scene, options);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return 1;

  // The ranks agree on the grid, the statistics, the transfer function and the camera.
  uint64_t mine = sceneFingerprint(grid, scene, camera), first = mine;
  MPI_Bcast(&first, 1, MPI_UINT64_T, 0, comm);
  if (anyFailed(mine == first ? ""
                              : "this rank read another volume, transfer function or camera "
                                "than rank 0 (are the files the same on every node?)",
                comm))
    return 1;

  // One slab grid for all: each rank classifies its volume and finds the nearest kernel among
  // its own brick's splats; the least over the ranks is where the whole volume's partition
  // starts its grid (its nearest kernel), so every brick cuts the one-process picture's slabs.
  ClassifiedSplats splats;
  double front = INFINITY;
  try {
    if (!brick.empty()) {
      splats = classifySplats(scene.volume, scene.transferFunction, splatClassification(settings));
      front = brickKernelFront(scene.volume, localBrick, splats, camera, settings, w, h);
    }
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return 1;
  double anchor = INFINITY;
  MPI_Allreduce(&front, &anchor, 1, MPI_DOUBLE, MPI_MIN, comm);
  // Nothing visible anywhere: any shared grid will do.
  if (!std::isfinite(anchor)) anchor = cornerSlabAnchor(scene.volume, camera, settings, w, h);

  // This rank's picture: premultiplied RGBA floats (composite), the optical depth (X-ray) or
  // the maximum (MIP); nothing where the brick is empty.
  std::vector<float> picture(size_t(w) * size_t(h) * 4, 0.0f);
  double renderMs = 0.0;
  std::string note;
  try {
    if (!brick.empty())
      picture =
          renderBrick(scene.volume, localBrick, scene.transferFunction, camera, settings, w, h,
                      anchor, options.backend, options.shaderDir, &splats, &note, &renderMs);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return 1;
  if (!note.empty() && rank == 0) std::cerr << "ewaview-mpi: " << note << std::endl;
  const IndexView view = indexView(camera, grid.origin, grid.direction, grid.spacing);

  // Composite: blended in visibility order, or summed (X-ray) or maximal (MIP) per pixel.
  std::vector<float> whole;
  double compositeMs = 0.0;
  try {
    const auto start = Clock::now();
    if (settings.mode == RenderMode::Composite) {
      IceTCompositor compositor(comm);
      whole = compositor.blend(picture, w, h, visibilityOrder(split, view));
    } else {
      whole =
          settings.mode == RenderMode::XRay ? reduceSum(picture, comm) : reduceMax(picture, comm);
    }
    compositeMs = msSince(start);
  } catch (const std::exception& e) {
    abortAll(e.what(), comm);
  }

  // Each rank's figures for --stats: its frame, the voxels it read and its peak memory.
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double ours[3] = {renderMs, double(voxelsRead), double(usage.ru_maxrss) / 1024.0};
  std::vector<double> figures(size_t(size) * 3, 0.0);
  MPI_Gather(ours, 3, MPI_DOUBLE, figures.data(), 3, MPI_DOUBLE, 0, comm);
  int status = 0;
  if (rank == 0) {
    try {
      Image8 image = finishPicture(whole, w, h, settings);
      if (options.axes)
        drawStrokes(image, orientationAxes(camera.rotation(), grid.patientFrame,
                                           axesPlacement(image.width, image.height)));
      writePng(options.output, image);
      if (options.stats) {
        std::ostringstream json;
        json << "{\"ranks\":" << size << ",\"width\":" << w << ",\"height\":" << h
             << ",\"composite_ms\":" << compositeMs
             << ",\"picture_bytes\":" << picture.size() * sizeof(float) << ",\"ghost\":["
             << ghost[0] << "," << ghost[1] << "," << ghost[2] << "],\"bricks\":[";
        for (int r = 0; r < size; ++r) {
          const VoxelBox& b = split.bricks[size_t(r)];
          const double* f = figures.data() + size_t(r) * 3;
          json << (r ? "," : "") << "{\"rank\":" << r << ",\"low\":[" << b.low[0] << "," << b.low[1]
               << "," << b.low[2] << "],\"high\":[" << b.high[0] << "," << b.high[1] << ","
               << b.high[2] << "],\"render_ms\":" << f[0] << ",\"voxels_read\":" << (long long)f[1]
               << ",\"peak_rss_mb\":" << f[2] << "}";
        }
        json << "]}";
        std::cout << json.str() << std::endl;
      }
    } catch (const std::exception& e) {
      std::cerr << "ewaview-mpi: " << oneLine(e.what()) << std::endl;
      status = 1;
    }
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, comm);
  return status;
}

}  // namespace ewa::dist
