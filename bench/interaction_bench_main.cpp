// ewaview-interact-bench: replays a recorded camera path the way the viewer draws it while
// moving (adaptive level of detail), then the full-quality frame it refines to in budgeted
// steps, beside the full-quality frame time at the same cameras as the baseline, in the same run.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <vector>

#include "app/options.h"
#include "app/scene.h"
#include "bench/bench_support.h"
#include "core/camera_path.h"
#include "core/lod_policy.h"
#include "gl/shader_library.h"
#include "io/volume_loader.h"
#include "platform/headless_context.h"
#include "render/lod_renderer.h"
#include "render/renderer_factory.h"
#include "render/splat_renderer.h"

namespace ewa {
namespace {

double median(const std::vector<double>& v) {
  return summarize(v).median;
}

// "FILE" or "FILE@X,Y,Z@TYPE@SX,SY,SZ@ENDIAN" for headerless raw data (MRbrain.raw).
Options optionsFor(const std::string& spec, int size) {
  Options o;
  o.width = o.height = size;
  const size_t at = spec.find('@');
  o.file = spec.substr(0, at);
  if (at != std::string::npos) {
    std::vector<std::string> parts;
    std::stringstream rest(spec.substr(at + 1));
    for (std::string p; std::getline(rest, p, '@');) parts.push_back(p);
    if (parts.size() != 4)
      throw std::runtime_error(spec + ": raw spec needs @dims@type@spacing@endian");
    o.rawDims = parts[0];
    o.rawType = parts[1];
    o.rawSpacing = parts[2];
    o.rawEndian = parts[3];
  }
  return o;
}

std::vector<std::string> defaultVolumes(const std::string& d) {
  return {d + "/nucleon/nucleon.nrrd",
          d + "/headmr/HeadMRVolume.mhd",
          d + "/neghip/neghip.slc",
          d + "/headsq/quarter.nhdr",
          d + "/tooth/tooth.nrrd",
          d + "/walnut/walnut.dat",
          d + "/fetal-t2/template_T2.nrrd",
          d + "/hydrogen/hydrogenatom.dat",
          d + "/cthead/CThead.nhdr",
          d + "/mrbrain/MRbrain.raw@256,256,109@uint16@1,1,2@big",
          d + "/lidc2/LIDC2.mha",
          d + "/engine/engine.nhdr",
          d + "/aneurism/aneurism.nhdr",
          d + "/bonsai/bonsai.nhdr",
          d + "/dicom-pet",
          d + "/nifti/anatomical.nii",
          d + "/nifti/example4d.nii.gz",
          d + "/nifti/example_nifti2.nii.gz",
          d + "/nifti/functional.nii",
          d + "/nifti/standard.nii.gz"};
}

// The MR DICOM stack comes zipped: unpacked (with unzip) into a temporary folder to be read.
std::string unpackedMrStack(const std::string& d) {
  const std::string zip = d + "/dicom-mr-stack/data.zip";
  const std::string out = (std::filesystem::temp_directory_path() / "ewaview-bench-mr").string();
  if (!std::filesystem::exists(zip)) return "";
  const std::string command = "unzip -q -o '" + zip + "' -d '" + out + "' >/dev/null 2>&1";
  return std::system(command.c_str()) == 0 ? out + "/data" : "";
}

int run(int argc, char** argv) {
  CLI::App app{"ewaview-interact-bench: moving (adaptive level of detail) vs full-quality frames"};
  std::vector<std::string> files;
  std::string pathFile = std::string(EWA_ASSET_DIR) + "/../bench/interaction_path.txt";
  int size = 512, baselineEvery = 6;
  double target = 100.0, refineDelay = 150.0, budget = 30.0;
  std::string backend = "osmesa";
  app.add_option("files", files,
                 "Volumes, FILE or FILE@X,Y,Z@TYPE@SX,SY,SZ@ENDIAN for raw (default: every "
                 "volume in ../shared/data up to 256^3 that ewaview reads)");
  app.add_option("--path", pathFile, "Camera path file (default bench/interaction_path.txt)");
  app.add_option("--size", size, "Window width and height (default 512)")
      ->check(CLI::Range(16, 8192));
  app.add_option("--target", target, "Moving frame-time target in ms (default 100)");
  app.add_option("--refine-delay", refineDelay, "Quiet ms before full quality (default 150)");
  app.add_option("--budget", budget,
                 "Renderer ms per UI frame for the progressive full-quality frame (default 30)");
  app.add_option("--baseline-every", baselineEvery,
                 "Full-quality baseline at every Nth camera of the path (default 6)")
      ->check(CLI::Range(1, 100000));
  addBackendOption(app, backend);
  CLI11_PARSE(app, argc, argv);
  if (files.empty()) {
    const std::string data = sharedDataDir();
    for (const std::string& f : defaultVolumes(data))
      if (std::filesystem::exists(f.substr(0, f.find('@')))) files.push_back(f);
    if (const std::string mr = unpackedMrStack(data); !mr.empty()) files.push_back(mr);
  }
  const std::vector<CameraStep> path = loadCameraPath(pathFile);

  auto context = platform::createHeadlessContext(platform::parseHeadlessBackend(backend));
  std::printf("# %s, %dx%d, path %s (%zu frames), target %.0f ms, refine after %.0f ms quiet\n",
              context->description().c_str(), size, size,
              std::filesystem::path(pathFile).filename().string().c_str(), path.size(), target,
              refineDelay);
  // last: the level of the path's last moving frame; at 0 the window shows full quality
  // already and starts no refinement (Viewer), so refine is what it would cost, not a wait.
  std::printf("%-13s %9s %8s | %8s %8s %6s %-9s %4s | %8s %8s %6s %8s | %7s\n", "volume", "splats",
              "lod_ms", "move_med", "move_max", "<=tgt", "levels", "last", "full_med", "refine",
              "steps", "max_step", "speedup");
  const gl::ShaderLibrary shaders;
  for (const std::string& spec : files) {
    const Options o = optionsFor(spec, size);
    Scene scene;
    try {
      scene = loadScene(o);
    } catch (const std::exception& e) {
      std::printf("%-13s skipped: %s\n", std::filesystem::path(o.file).stem().string().c_str(),
                  e.what());
      continue;
    }
    auto t = BenchClock::now();
    LodVolumes coarse = buildLodVolumes(scene.volume);
    const double lodBuildMs = millisecondsSince(t);
    // The window's way: the levels share one set of programs.
    std::shared_ptr<SplatProgramSet> programs;
    LodRenderer lod(
        [&shaders, &programs] { return createRenderer(RendererKind::Splat, shaders, &programs); });
    lod.setVolume(scene.volume, std::move(coarse));
    lod.setTransferFunction(scene.transferFunction);
    const Camera start = initialCamera(scene.volume, o);
    // Classification and upload of every level happen on first use: not part of the timings.
    for (int level = 0; level <= lod.coarsestLevel(); ++level)
      lod.render(level, start, o.render, size, size);
    // As the window does: the first full-quality frame picks the first moving level.
    t = BenchClock::now();
    lod.render(0, start, o.render, size, size);
    const double firstFullMs = millisecondsSince(t);
    const size_t splats = lod.last().stats().splatsTotal;

    LodPolicy policy(target, refineDelay);
    policy.setCoarsestLevel(lod.coarsestLevel());
    policy.startFromFullQuality(firstFullMs);
    Camera cam = start;
    std::vector<double> moving, full;
    std::vector<int> levelUse(LodPolicy::kLevelCount, 0);
    int within = 0, lastLevel = 0;
    for (size_t f = 0; f < path.size(); ++f) {
      applyCameraStep(cam, path[f]);
      const int level = lastLevel = policy.movingLevel();
      t = BenchClock::now();
      lod.render(level, cam, o.render, size, size);
      const double ms = millisecondsSince(t);
      policy.reportMovingFrame(level, ms);
      moving.push_back(ms);
      ++levelUse[size_t(level)];
      within += ms <= target;
      if (f % size_t(baselineEvery) == 0) {
        t = BenchClock::now();
        lod.render(0, cam, o.render, size, size);
        full.push_back(millisecondsSince(t));
      }
    }
    // Input stops: the viewer waits refineDelay, then refines full quality in steps of about
    // `budget` ms (one per UI frame); the worst step bounds the UI frame while refining.
    t = BenchClock::now();
    double worstStep = 0.0;
    int steps = 0;
    lod.beginFull(cam, o.render, size, size);
    worstStep = millisecondsSince(t);
    for (bool done = false; !done; ++steps) {
      const auto s = BenchClock::now();
      done = lod.stepFull(budget);
      worstStep = std::max(worstStep, millisecondsSince(s));
    }
    const double refine = refineDelay + millisecondsSince(t);
    std::string levels;
    for (int l = 0; l < LodPolicy::kLevelCount; ++l)
      if (levelUse[size_t(l)])
        levels += (levels.empty() ? "" : ",") + std::to_string(l) + "x" +
                  std::to_string(levelUse[size_t(l)]);
    const double mm = median(moving), fm = median(full);
    std::printf(
        "%-13s %9zu %8.0f | %8.1f %8.1f %3d/%-2zu %-9s %4d | %8.1f %8.1f %6d %8.1f | %7.1f\n",
        std::filesystem::path(o.file).stem().string().c_str(), splats, lodBuildMs, mm,
        *std::max_element(moving.begin(), moving.end()), within, moving.size(), levels.c_str(),
        lastLevel, fm, refine, steps, worstStep, fm / std::max(mm, 1e-3));
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace
}  // namespace ewa

int main(int argc, char** argv) {
  return ewa::benchmarkMain("ewaview-interact-bench", ewa::run, argc, argv);
}
