// ewaview-classify-bench: classification (the splats a transfer function keeps, their values
// and normals) on one thread beside all of the machine's cores, in the same run.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/scene.h"
#include "bench/bench_support.h"
#include "core/parallel_chunks.h"
#include "core/splat_attributes.h"
#include "render/renderer.h"

namespace ewa {
namespace {

int run(int argc, char** argv) {
  CLI::App app{"ewaview-classify-bench: classification on one thread beside all cores"};
  std::vector<std::string> files, synthetic;
  int repeats = 3;
  unsigned threads = 0;
  std::string mode = "post";
  app.add_option("files", files, "Volumes (default: the default volume)");
  app.add_option("--synthetic", synthetic, "Also a synthetic volume NAME:N (repeatable)");
  app.add_option("--repeats", repeats, "Timed runs each way, interleaved (default 3)")
      ->check(CLI::Range(1, 100));
  app.add_option("--threads", threads,
                 "Threads of the parallel runs (default: the machine's cores, at most 16)")
      ->check(CLI::Range(1, 256));
  app.add_option("--classification", mode, "post (default) or pre")
      ->check(CLI::IsMember({"pre", "post"}));
  CLI11_PARSE(app, argc, argv);
  std::vector<Options> scenes;
  for (const std::string& f : files) {
    Options o;
    o.file = f;
    scenes.push_back(o);
  }
  for (const std::string& s : synthetic) {
    Options o;
    o.synthetic = s;
    scenes.push_back(o);
  }
  if (scenes.empty()) scenes.emplace_back();
  const unsigned parallel = workerThreads(threads);
  std::printf("# median of %d runs each way, interleaved; ms; %s-classified; %u threads\n", repeats,
              mode.c_str(), parallel);
  std::printf("%-24s %12s %12s %10s %10s %8s\n", "volume", "voxels", "splats", "1_thread",
              "parallel", "ratio");
  for (const Options& o : scenes) {
    const Scene scene = loadScene(o);
    RenderSettings settings;
    parseClassificationMode(mode, &settings.classification.mode);
    const Classification c = splatClassification(settings);
    std::vector<double> one, all;
    size_t splats = 0;
    for (int r = 0; r < repeats; ++r) {
      for (unsigned t : {1u, parallel}) {
        const auto start = BenchClock::now();
        const ClassifiedSplats s =
            classifySplats(scene.volume, scene.transferFunction, c, SIZE_MAX, t);
        (t == 1 ? one : all).push_back(millisecondsSince(start));
        splats = s.splats.size();
      }
    }
    const double oneMs = summarize(one).median, allMs = summarize(all).median;
    std::printf("%-24s %12lld %12zu %10.1f %10.1f %8.2f\n", scene.name.c_str(),
                static_cast<long long>(scene.volume.voxelCount()), splats, oneMs, allMs,
                allMs / oneMs);
  }
  return 0;
}

}  // namespace
}  // namespace ewa

int main(int argc, char** argv) {
  return ewa::benchmarkMain("ewaview-classify-bench", ewa::run, argc, argv);
}
