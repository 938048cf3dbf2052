// renderDistributed: load and agree, split, render the brick, composite, write on rank 0.
#include "dist/mpi_render.h"

#include <algorithm>
#include <chrono>
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
#include "app/turntable.h"
#include "core/orientation_axes.h"
#include "core/stopwatch.h"
#include "core/volume_orientation.h"
#include "dist/brick_clip.h"
#include "dist/brick_ghosts.h"
#include "dist/brick_split.h"
#include "dist/mpi_brick_renderer.h"
#include "dist/mpi_brick_source.h"
#include "dist/mpi_collective.h"
#include "dist/mpi_session.h"
#include "gl/shader_library.h"
#include "io/frame_sink.h"
#include "io/input_guard.h"
#include "io/png_io.h"
#include "render/splat_renderer.h"

namespace ewa::dist {

namespace {

using Clock = std::chrono::steady_clock;

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

double brickKernelFront(const Volume& volume, const VoxelBox& brick, const SplatSet& set,
                        const AttributeList& attributes, const Camera& world,
                        const RenderSettings& settings, int width, int height) {
  const Camera camera = cameraInVolumeFrame(world, volume);
  return nearestKernelFront(set, attributes, volume.origin(), camera.viewMatrix(),
                            footprintParams(settings, volume.spacing()).cullDepth,
                            depthExtent(volume, camera, settings, width, height), [&](size_t m) {
                              const PackedSplat& p = set.splats()[m];
                              const int64_t i = SplatSet::i(p), j = SplatSet::j(p),
                                            k = SplatSet::k(p);
                              return i >= brick.low[0] && i < brick.high[0] && j >= brick.low[1] &&
                                     j < brick.high[1] && k >= brick.low[2] && k < brick.high[2];
                            });
}

double brickKernelFront(const Volume& volume, const VoxelBox& brick, const ClassifiedSplats& splats,
                        const Camera& world, const RenderSettings& settings, int width,
                        int height) {
  return brickKernelFront(volume, brick, splats.splats, splats.attributes, world, settings, width,
                          height);
}

namespace {

uint8_t toByte(double v) {
  return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

}  // namespace

std::string distributedUsageProblem(const Options& o) {
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
  renderer.setVolume(volume);
  ClassifiedSplats own;
  if (!splats) {
    own = classifySplats(volume, tf, splatClassification(settings));
    splats = &own;
  }
  // X-ray and MIP draw one slab of unbounded thickness: no grid to share.
  const double anchor = settings.mode == RenderMode::Composite ? slabAnchor : NAN;
  std::vector<float> picture = renderer.render(tf, camera, settings, width, height, anchor, splats);
  if (ms) *ms = millisecondsSince(start);
  if (note) *note = renderer.note();
  if (picture.size() != size_t(width) * size_t(height) * 4)
    throw std::runtime_error("the renderer returned no picture");
  return picture;
}

namespace {

// The files an output must not replace: the volume's, the transfer function's, the bookmarks.
std::vector<std::string> inputFiles(const DistributedSession& session, const Options& options) {
  std::vector<std::string> inputs = session.volume().sourceFiles();
  for (const std::string& file : {options.file, options.tfFile, options.bookmarks})
    if (!file.empty()) inputs.push_back(file);
  return inputs;
}

// Rank 0's picture of a frame: the final pass over the composite, and the axes where asked.
Image8 finishedFrame(const DistributedSession& session, const std::vector<float>& whole,
                     const Camera& camera, const RenderSettings& settings, const Options& o) {
  Image8 image = finishPicture(whole, o.width, o.height, settings);
  if (o.axes)
    drawStrokes(image, orientationAxes(camera.rotation(), session.grid().patientFrame,
                                       axesPlacement(image.width, image.height)));
  return image;
}

// --turntable and --tour: ewaview's camera path and frame loop (writeFrames), each frame one
// collective DistributedSession::render; rank 0 alone opens the sink, writes and shows progress.
// An error on any rank stops every rank after one line.
int renderDistributedFrames(DistributedSession& session, const Options& o) {
  const MPI_Comm comm = session.comm();
  const int rank = session.rank();
  std::string error;
  FramePath path;
  std::unique_ptr<FrameSink> sink;
  try {
    // Every rank reads the bookmarks of a tour, so each knows the path.
    path = framePath(o, session.initialCamera(), o.file, session.name());
    if (rank == 0) {
      const std::vector<std::string> inputs = inputFiles(session, o);
      refuseToReplaceInputs(o.output, inputs);
      sink = openFrameSink(o.output, path.count, o.fps);
      for (int f = 0; f < path.count; ++f) refuseToReplaceInputs(sink->fileOf(f), inputs);
    }
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return 1;
  const DrawFrame draw = [&](int, const TourStop& stop, Image8* picture, std::string* note) {
    RenderSettings settings = o.render;
    settings.clip = stop.clip;
    std::vector<float> whole;
    if (!session.render(stop.camera, settings, session.transferFunction(), o.width, o.height,
                        &whole))
      return false;
    if (rank == 0) {
      *picture = finishedFrame(session, whole, stop.camera, settings, o);
      *note = session.note();
    }
    return true;
  };
  const bool done = writeFrames(path, sink.get(), "ewaview-mpi", draw,
                                [comm](const std::string& e) { return anyFailed(e, comm); });
  return done ? 0 : 1;
}

}  // namespace

int renderDistributed(const Options& options, MPI_Comm comm) {
  const std::unique_ptr<DistributedSession> session = DistributedSession::open(options, comm);
  if (!session) return 1;
  if (options.turntable > 0 || options.tour > 0) return renderDistributedFrames(*session, options);
  const int rank = session->rank();
  const Camera& camera = session->initialCamera();
  const RenderSettings& settings = options.render;
  const int w = options.width, h = options.height;
  int status = 0;
  if (rank == 0) {
    // The output must not replace an input (the volume's files, the transfer function's).
    try {
      refuseToReplaceInputs(options.output, inputFiles(*session, options));
    } catch (const std::exception& e) {
      std::cerr << "ewaview-mpi: " << oneLine(e.what()) << std::endl;
      status = 1;
    }
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, comm);
  if (status != 0) return status;

  std::vector<float> whole;
  if (!session->render(camera, settings, session->transferFunction(), w, h, &whole)) return 1;
  if (rank == 0 && !session->note().empty())
    std::cerr << "ewaview-mpi: " << session->note() << std::endl;
  if (rank == 0) {
    try {
      writePng(options.output, finishedFrame(*session, whole, camera, settings, options));
      if (options.stats) std::cout << frameStatsJson(*session, w, h) << std::endl;
    } catch (const std::exception& e) {
      std::cerr << "ewaview-mpi: " << oneLine(e.what()) << std::endl;
      status = 1;
    }
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, comm);
  return status;
}

std::string frameStatsJson(const DistributedSession& session, int w, int h) {
  const std::vector<RankFigures>& figures = session.figures();
  const std::array<int64_t, 3>& ghost = session.ghost();
  std::ostringstream json;
  json << "{\"ranks\":" << session.size() << ",\"width\":" << w << ",\"height\":" << h
       << ",\"composite_ms\":" << session.slowestCompositeMs()
       << ",\"picture_bytes\":" << size_t(w) * size_t(h) * 4 * sizeof(float) << ",\"ghost\":["
       << ghost[0] << "," << ghost[1] << "," << ghost[2] << "],\"bricks\":[";
  for (size_t r = 0; r < figures.size(); ++r) {
    const VoxelBox& b = session.split().bricks[r];
    const RankFigures& f = figures[r];
    json << (r ? "," : "") << "{\"rank\":" << r << ",\"low\":[" << b.low[0] << "," << b.low[1]
         << "," << b.low[2] << "],\"high\":[" << b.high[0] << "," << b.high[1] << "," << b.high[2]
         << "],\"render_ms\":" << f.renderMs << ",\"composite_ms\":" << f.compositeMs
         << ",\"bytes_sent\":" << (long long)f.bytesSent << ",\"splats\":" << (long long)f.splats
         << ",\"voxels_read\":" << (long long)f.voxelsRead << ",\"peak_rss_mb\":" << f.peakRssMb
         << "}";
  }
  json << "]}";
  return json.str();
}

}  // namespace ewa::dist
