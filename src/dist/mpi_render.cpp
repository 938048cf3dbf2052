// renderDistributed: load and agree, split, render the brick, composite, write on rank 0.
#include "dist/mpi_render.h"

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
#include "dist/brick_clip.h"
#include "dist/brick_split.h"
#include "dist/icet_compositor.h"
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

// What every rank must hold the same before the first frame: the volume's grid, value range
// and histogram (behind splat quantization and the default transfer function), the transfer
// function and the camera. Every rank reads the whole volume, so these agree unless the ranks
// read different files.
uint64_t sceneFingerprint(const Scene& scene, const Camera& camera) {
  Fingerprint f;
  const Volume& v = scene.volume;
  for (int a = 0; a < 3; ++a) {
    f.add(double(v.dims()[a]));
    f.add(v.spacing()[a]);
    f.add(v.origin()[a]);
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
                            const RenderSettings& settings, int width, int height) {
    context_->makeCurrent();
    renderer_->setVolume(volume);
    renderer_->setTransferFunction(tf);
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

int renderDistributed(const Options& options, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);

  // Every rank reads the scene; a rank that cannot (a file missing there) says so for all.
  Scene scene;
  Camera camera;
  std::string error;
  try {
    scene = loadScene(options);
    camera = initialCamera(scene.volume, options);
    if (rank == 0) refuseToOverwriteInputs(options.output, scene, options);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return 1;

  // The ranks agree on the data, the transfer function and the camera before the first frame.
  uint64_t mine = sceneFingerprint(scene, camera), first = mine;
  MPI_Bcast(&first, 1, MPI_UINT64_T, 0, comm);
  if (anyFailed(mine == first ? ""
                              : "this rank read another volume, transfer function or camera "
                                "than rank 0 (are the files the same on every node?)",
                comm))
    return 1;

  const Volume& volume = scene.volume;
  const BrickSplit split = splitBricks(VoxelWeights(volume.dims()), size);
  const VoxelBox& brick = split.bricks[size_t(rank)];
  RenderSettings settings = options.render;
  error = addBrickPlanes(volume, brick, &settings.clip);
  if (anyFailed(error, comm)) return 1;

  // This rank's picture: premultiplied RGBA floats (composite), the optical depth (X-ray) or
  // the maximum (MIP); nothing where the brick is empty.
  const int w = options.width, h = options.height;
  std::vector<float> picture(size_t(w) * size_t(h) * 4, 0.0f);
  double renderMs = 0.0;
  std::string note;
  try {
    if (!brick.empty()) {
      BrickRenderer renderer(options.backend, options.shaderDir);
      const auto start = Clock::now();
      picture = renderer.render(volume, scene.transferFunction, camera, settings, w, h);
      renderMs = msSince(start);
      note = renderer.note();
      if (picture.size() != size_t(w) * size_t(h) * 4)
        throw std::runtime_error("the renderer returned no picture");
    }
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return 1;
  if (!note.empty() && rank == 0) std::cerr << "ewaview-mpi: " << note << std::endl;

  // Composite: blended in visibility order, or summed (X-ray) or maximal (MIP) per pixel.
  std::vector<float> whole;
  double compositeMs = 0.0;
  try {
    const auto start = Clock::now();
    if (settings.mode == RenderMode::Composite) {
      IceTCompositor compositor(comm);
      whole = compositor.blend(picture, w, h, visibilityOrder(split, indexView(camera, volume)));
    } else {
      whole =
          settings.mode == RenderMode::XRay ? reduceSum(picture, comm) : reduceMax(picture, comm);
    }
    compositeMs = msSince(start);
  } catch (const std::exception& e) {
    abortAll(e.what(), comm);
  }

  std::vector<double> renderTimes(size_t(size), 0.0);
  MPI_Gather(&renderMs, 1, MPI_DOUBLE, renderTimes.data(), 1, MPI_DOUBLE, 0, comm);
  int status = 0;
  if (rank == 0) {
    try {
      Image8 image = finishPicture(whole, w, h, settings);
      if (options.axes)
        drawStrokes(image, orientationAxes(camera.rotation(), volume.patientFrame(),
                                           axesPlacement(image.width, image.height)));
      writePng(options.output, image);
      if (options.stats) {
        std::ostringstream json;
        json << "{\"ranks\":" << size << ",\"width\":" << w << ",\"height\":" << h
             << ",\"composite_ms\":" << compositeMs << ",\"bricks\":[";
        for (int r = 0; r < size; ++r) {
          const VoxelBox& b = split.bricks[size_t(r)];
          json << (r ? "," : "") << "{\"rank\":" << r << ",\"low\":[" << b.low[0] << "," << b.low[1]
               << "," << b.low[2] << "],\"high\":[" << b.high[0] << "," << b.high[1] << ","
               << b.high[2] << "],\"render_ms\":" << renderTimes[size_t(r)] << "}";
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
