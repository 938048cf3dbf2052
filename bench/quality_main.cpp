// ewaview-quality: the filter-quality benchmark. Renders Swan's checkerboard and Zwicker's zebra
// sheets with each filter mode, compares them with a reference integrated along rays on the CPU
// (supersampled, low-passed), prints a Markdown table and writes a montage per scene.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/option_binding.h"
#include "bench/bench_support.h"
#include "bench/quality_benchmark.h"
#include "bench/quality_report.h"
#include "core/kernel_lattice.h"
#include "gl/shader_library.h"
#include "platform/headless_context.h"
#include "render/gl_limits.h"

namespace ewa {
namespace {

// Beyond this the reference's float buffers (about 40 bytes a pixel) would not fit comfortably.
constexpr int kMaxReferenceSize = 8192;

// quality_<spec>.png, with ':' as '_' and the sheet opacity when it was replaced.
std::string fileNameOf(const std::string& spec, double sheetOpacity) {
  std::string s = spec;
  std::replace(s.begin(), s.end(), ':', '_');
  if (sheetOpacity > 0.0) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "_opacity%g", sheetOpacity);
    s += buf;
  }
  return "quality_" + s + ".png";
}

int run(int argc, char** argv) {
  CLI::App app{
      "ewaview-quality: filter quality (ewa, swan, plain) against a reference integrated along "
      "rays on the CPU, on the checkerboard and zebra sheets"};
  QualityOptions o;
  std::string outputDir, backend = "osmesa";
  std::vector<std::string> only;
  bool noReferenceFlicker = false, noSplatReference = false;
  app.add_option("--size", o.size, "Image width and height (default 256)")
      ->check(CLI::Range(16, 2048));
  app.add_option("--supersample", o.supersample,
                 "Reference rays per pixel along each axis (default 8)")
      ->check(CLI::Range(1, 16));
  app.add_option("--frames", o.frames,
                 "Sub-pixel camera moves for the flicker (default 8; 0: none)")
      ->check(CLI::Range(0, 1000));
  app.add_option("--step", o.stepPixels, "Image motion per move in pixels (default 0.25)")
      ->check(CLI::Range(0.001, 100.0));
  app.add_option("--output-dir", outputDir, "Write a montage PNG per scene into this folder");
  app.add_option("--scene", only, "Only these scenes (checkerboard:10, zebra:2, zebra:4)");
  app.add_option("--sheet-opacity", o.sheetOpacity,
                 "Opacity of one voxel of the sheets, replacing their own 0.98")
      ->check(CLI::Range(0.001, 0.999));
  addTableOption(app, "--kernel-width", o.kernelWidth);  // ewaview's, with its default
  addTableOption(app, "--cutoff", o.cutoff);
  app.add_flag("--no-reference-flicker", noReferenceFlicker,
               "Skip rendering the reference at every move (its own flicker)");
  app.add_flag("--no-splat-reference", noSplatReference,
               "Skip the old reference (EWA splats at the same supersampling) and its distance "
               "to the ray-integrated one");
  addBackendOption(app, backend);
  CLI11_PARSE(app, argc, argv);
  o.referenceFlicker = !noReferenceFlicker;
  o.splatReference = !noSplatReference;

  std::vector<QualityScene> scenes;
  for (const QualityScene& s : qualityScenes())
    if (only.empty() || std::find(only.begin(), only.end(), s.spec) != only.end())
      scenes.push_back(s);
  for (const std::string& name : only)
    if (std::none_of(scenes.begin(), scenes.end(),
                     [&](const QualityScene& s) { return s.spec == name; }))
      throw std::invalid_argument("--scene " + name +
                                  ": unknown (expected checkerboard:10, zebra:2 or zebra:4)");
  if (!outputDir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(outputDir, error);
    if (error || !std::filesystem::is_directory(outputDir))
      throw std::runtime_error(outputDir + ": cannot create the output folder");
  }

  auto context = platform::createHeadlessContext(platform::parseHeadlessBackend(backend));
  const int limit = std::min(kMaxReferenceSize, maxRenderTargetSize());
  const int needed = referenceRenderSize(o);
  if (needed > limit)
    throw std::invalid_argument("--size " + std::to_string(o.size) + " --supersample " +
                                std::to_string(o.supersample) + ": the reference needs a " +
                                std::to_string(needed) + " pixel square image, above the limit " +
                                std::to_string(limit) + " (tiling is not implemented)");
  const gl::ShaderLibrary shaders;
  SplatRenderer renderer(shaders);
  char opacityText[32];
  std::snprintf(opacityText, sizeof opacityText, "%g", o.sheetOpacity);
  const std::string opacity = o.sheetOpacity > 0.0 ? opacityText : "0.98 (the volumes' own)";
  std::printf(
      "# %s; %dx%d, reference integrated along %dx%d rays a pixel (%d with margin), Gaussian "
      "sigma %.2f px; "
      "%d moves of %.3f px; sheet opacity %s; kernel width %.2f, cutoff %g\n\n",
      context->description().c_str(), o.size, o.size, o.supersample, o.supersample, needed, o.sigma,
      o.frames, o.stepPixels, opacity.c_str(), o.kernelWidth, o.cutoff);
  std::vector<SceneQuality> results;
  for (const QualityScene& scene : scenes) {
    const SyntheticVolume volume = makeSyntheticVolume(scene.spec);
    const auto start = BenchClock::now();
    results.push_back(measureScene(renderer, scene, volume, o));
    const double seconds = secondsSince(start);
    const SceneQuality& q = results.back();
    std::fprintf(stderr,
                 "%s: k = %.1f, sheet %zu px, beyond k %zu px, anisotropic %zu px; "
                 "the old reference (EWA splats) differs by RMSE %.4f (beyond k %.4f); %.1f s\n",
                 scene.spec.c_str(), q.regions.k, maskCount(q.regions.sheet),
                 maskCount(q.regions.beyondK), maskCount(q.regions.anisotropic),
                 q.splatReferenceRmseAll, q.splatReferenceRmseBeyond, seconds);
    if (!outputDir.empty()) {
      const std::string path =
          (std::filesystem::path(outputDir) / fileNameOf(scene.spec, o.sheetOpacity)).string();
      writePng(path, qualityMontage(q));
    }
  }
  std::printf("%s", qualityTable(results).c_str());
  return 0;
}

}  // namespace
}  // namespace ewa

int main(int argc, char** argv) {
  return ewa::benchmarkMain("ewaview-quality", ewa::run, argc, argv);
}
