// runDistributedWindow: rank 0's window (or scripted frames) and the other ranks' frame loop.
#include "dist/mpi_window.h"

#include <GLFW/glfw3.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/one_line.h"
#include "app/scene.h"
#include "app/window_config.h"
#include "core/volume_downsample.h"
#include "dist/mpi_brick_renderer.h"
#include "dist/mpi_session.h"
#include "dist/mpi_window_renderer.h"
#include "io/png_io.h"
#include "platform/glfw_window_context.h"
#include "ui/viewer.h"

namespace ewa::dist {

namespace {

// The stand-in's size: the whole volume up to 16 Mi voxels (engine's 8 Mi, CT heads), which
// rank 0 holds besides its brick; larger volumes averaged down to fit.
constexpr int64_t kStandInVoxels = int64_t(1) << 24;

Options parseQuietly(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  Options options;
  std::ostringstream quiet;
  std::streambuf* out = std::cout.rdbuf(quiet.rdbuf());
  const ParseResult parsed = parseCommandLine(int(argv.size()), argv.data(), &options);
  std::cout.rdbuf(out);
  if (!parsed.run || parsed.exitCode != 0)
    throw std::runtime_error("a scripted frame's options do not parse: " + oneLine(quiet.str()));
  return options;
}

// EWAVIEW_MPI_SCRIPT: each line's frame through DistributedRenderer, as the window draws it.
int runScript(const std::string& script, int argc, char** argv, DistributedSession& session,
              const std::shared_ptr<ClusterLink>& link) {
  std::ifstream in(script);
  if (!in) throw std::runtime_error(script + ": cannot read the frame script");
  DistributedRenderer renderer(link, nullptr);
  const WholeGrid& g = session.grid();
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string output, word;
    if (!(words >> output)) continue;
    std::vector<std::string> args(argv, argv + argc);
    while (words >> word) args.push_back(word);
    const Options o = parseQuietly(args);
    const Camera camera =
        initialCameraForBounds(g.worldBoundsMin(), g.worldBoundsMax(), g.patientFrame, o);
    renderer.setTransferFunction(sceneTransferFunction(
        o, session.source().sidecar(), session.source().ownTransferFunction(), session.volume()));
    renderer.render(camera, o.render, o.width, o.height);
    writePng(output, renderer.readImage());
  }
  return 0;
}

int runWindow(const Options& options, DistributedSession& session,
              const std::shared_ptr<ClusterLink>& link) {
  ViewerConfig config;
  const std::string clipKey = options.synthetic.empty()
                                  ? std::filesystem::absolute(options.file).string()
                                  : "synthetic:" + session.name();
  const Options o = windowConfig(options, clipKey, &config);
  const WholeGrid& g = session.grid();
  config.camera = initialCameraForBounds(g.worldBoundsMin(), g.worldBoundsMax(), g.patientFrame, o);
  config.title = "ewaview-mpi: " + std::to_string(session.size()) + " ranks";
  config.fixedVolume =
      "ewaview-mpi's window shows the volume its ranks opened: run ewaview-mpi again for "
      "another file (nor is this one reloaded or saved here)";
  config.rendererFactory = [link](platform::GlContext& window) -> std::unique_ptr<Renderer> {
    auto* glfw = dynamic_cast<platform::GlfwWindowContext*>(&window);
    // This rank's brick is drawn on a hidden window of the same GL (made at its first frame,
    // on this thread, as GLFW asks).
    if (glfw)
      BrickRenderer::setContextFactory([library = glfw->glfw()] {
        platform::WindowOptions hidden;
        hidden.width = hidden.height = 16;
        hidden.visible = false;
        hidden.vsync = false;
        return std::make_unique<platform::GlfwWindowContext>(hidden, library);
      });
    auto renderer = std::make_unique<DistributedRenderer>(link, &window, [glfw] {
      if (glfw) glfwSetWindowShouldClose(glfw->window(), GLFW_TRUE);
    });
    // Full-quality frames on a worker where MPI may be called from it (mpi_main asks for
    // MPI_THREAD_SERIALIZED): the window answers while the ranks draw.
    int threading = MPI_THREAD_SINGLE;
    MPI_Query_thread(&threading);
    if (glfw && threading >= MPI_THREAD_SERIALIZED)
      renderer->setWorkerFrames([] { glfwMakeContextCurrent(nullptr); });
    return renderer;
  };
  config.statisticsLines = [link] { return link->statisticsLines(); };
  LoadedVolume initial;
  initial.volume =
      std::make_shared<Volume>(standInVolume(session.source(), session.volume(), kStandInVoxels));
  initial.tf = session.transferFunction();
  initial.name = session.name();
  if (options.synthetic.empty()) initial.path = std::filesystem::absolute(options.file).string();
  const int status = runViewer(std::move(initial), config);
  // The brick's hidden window keeps GLFW until the session ends; no new one is made after.
  BrickRenderer::setContextFactory(nullptr);
  return status;
}

}  // namespace

Volume standInVolume(BrickSource& source, const Volume& statistics, int64_t maxVoxels) {
  const WholeGrid& g = source.grid();
  const int64_t count = g.dims[0] * g.dims[1] * g.dims[2];
  int factor = 1;
  while (count / (int64_t(factor) * factor * factor) > maxVoxels) factor *= 2;
  Volume stand;
  if (factor == 1) {
    stand = source.read(VoxelRegion{{0, 0, 0}, g.dims});
  } else {
    // A slab of `layers` z-layers at a time, averaged down to one layer of the stand-in.
    const int64_t layers = downsampleAxisFactor(g.dims[2], factor);
    std::vector<uint8_t> bytes;
    Volume first;
    for (int64_t z = 0; z < g.dims[2]; z += layers) {
      Volume slab =
          downsampleVolume(source.read(VoxelRegion{
                               {0, 0, z}, {g.dims[0], g.dims[1], std::min(z + layers, g.dims[2])}}),
                           factor);
      bytes.insert(bytes.end(), slab.bytes().begin(), slab.bytes().end());
      if (z == 0) first = std::move(slab);
    }
    const std::array<int64_t, 3> dims{first.dims()[0], first.dims()[1],
                                      (g.dims[2] + layers - 1) / layers};
    glm::dvec3 spacing = first.spacing();
    spacing.z = g.spacing.z * double(layers);
    stand = Volume(dims, spacing, first.origin(), first.type(), std::move(bytes));
  }
  stand.setDirection(g.direction, g.patientFrame);
  stand.setValueStatistics(statistics.minValue(), statistics.maxValue(), statistics.histogram());
  return stand;
}

int runDistributedWindow(const Options& options, int argc, char** argv, MPI_Comm comm) {
  const std::unique_ptr<DistributedSession> session = DistributedSession::open(options, comm);
  if (!session) return 1;
  if (session->rank() != 0) return serveFrames(*session);
  const auto link = std::make_shared<ClusterLink>(*session);
  int status = 1;
  try {
    const char* script = std::getenv("EWAVIEW_MPI_SCRIPT");
    status = script && *script ? runScript(script, argc, argv, *session, link)
                               : runWindow(options, *session, link);
  } catch (const std::exception& e) {
    // A failed frame was told by its rank already.
    if (!link->failed()) std::cerr << "ewaview-mpi: " << oneLine(e.what()) << std::endl;
    status = 1;
  }
  if (link->failed()) return 1;  // the other ranks left their loop with the failed frame
  link->quit(status);
  return status;
}

}  // namespace ewa::dist
