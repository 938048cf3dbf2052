// ewaview-bench: EWA splatting frame times over a turntable, beside bare point sprites of the
// same sizes drawn in the same run.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "app/options.h"
#include "app/scene.h"
#include "bench/bench_sprites.h"
#include "bench/bench_support.h"
#include "bench/sprite_baseline.h"
#include "gl/shader_library.h"
#include "platform/headless_context.h"
#include "render/splat_renderer.h"

namespace ewa {
namespace {

int run(int argc, char** argv) {
  CLI::App app{"ewaview-bench: EWA splatting turntable timings beside bare point sprites"};
  std::vector<std::string> files;
  int frames = 90, size = 512;
  double step = 2.0;
  std::string backend = "osmesa";
  std::string partition = "auto";
  const std::string data = sharedDataDir();
  app.add_option("files", files, "Volumes (default: engine and bonsai from ../shared/data)");
  app.add_option("--frames", frames, "Turntable frames (default 90)")->check(CLI::Range(1, 3600));
  app.add_option("--step", step, "Degrees between frames (default 2)");
  app.add_option("--size", size, "Image width and height (default 512)")
      ->check(CLI::Range(16, 8192));
  app.add_option("--partition", partition,
                 "Where the slab partition is built: auto, gpu or cpu (default auto)")
      ->check(CLI::IsMember({"auto", "gpu", "cpu"}));
  addBackendOption(app, backend);
  CLI11_PARSE(app, argc, argv);
  PartitionMode partitionMode = PartitionMode::Auto;
  parsePartitionMode(partition, &partitionMode);
  if (files.empty()) files = {data + "/engine/engine.nhdr", data + "/bonsai/bonsai.nhdr"};

  auto context = platform::createHeadlessContext(platform::parseHeadlessBackend(backend));
  std::printf("# %s, %dx%d, %d frames, %.1f deg steps\n", context->description().c_str(), size,
              size, frames, step);
  const gl::ShaderLibrary shaders;
  SplatRenderer renderer(shaders);
  renderer.setPartition(partitionMode);
  std::printf("# slab partition: %s (%s)\n", renderer.gpuPartition() ? "gpu" : "cpu",
              partition.c_str());
  // --splatter auto (the default) may draw a GPU's frames in compute tiles: counted per volume.
  std::printf("%-14s %10s %10s %10s %10s %10s | %10s %10s %10s | %7s %11s\n", "volume", "splats",
              "ewa_med", "ewa_min", "ewa_max", "part_med", "bare_med", "bare_min", "bare_max",
              "ratio", "tile_frames");
  SpriteBaseline baseline(shaders);
  for (const std::string& file : files) {
    Options o;
    o.file = file;
    o.width = o.height = size;
    const Scene scene = loadScene(o);
    renderer.setVolume(scene.volume);
    renderer.setTransferFunction(scene.transferFunction);
    Camera cam = initialCamera(scene.volume, o);
    std::vector<double> ewaMs, partitionMs, bareMs;
    size_t drawn = 0;
    int tileFrames = 0;
    for (int f = 0; f < frames; ++f) {
      renderer.render(cam, o.render, size, size);
      tileFrames += renderer.stats().tiles ? 1 : 0;
      ewaMs.push_back(renderer.stats().renderMs);
      partitionMs.push_back(renderer.stats().partitionMs);
      drawn = std::max(drawn, renderer.stats().splatsDrawn);
      baseline.setSprites(spriteSizes(renderer, scene.volume, cam, o.render, size, size));
      bareMs.push_back(baseline.draw(size, size, halfFloatSlabs(o.render)));
      cam.orbit(step, 0.0);
    }
    const TimingSummary e = summarize(ewaMs), p = summarize(partitionMs), b = summarize(bareMs);
    std::printf("%-14s %10zu %10.1f %10.1f %10.1f %10.1f | %10.1f %10.1f %10.1f | %7.2f %11d\n",
                std::filesystem::path(file).stem().string().c_str(), drawn, e.median, e.min, e.max,
                p.median, b.median, b.min, b.max, e.median / b.median, tileFrames);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace
}  // namespace ewa

int main(int argc, char** argv) {
  return ewa::benchmarkMain("ewaview-bench", ewa::run, argc, argv);
}
