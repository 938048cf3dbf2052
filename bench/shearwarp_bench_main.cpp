// ewaview-shearwarp-bench: the structure of Schulze et al.'s Table 1 (seconds per frame of the
// standard and pre-integrated shear-warp variants over a 180-degree turntable at 512x512), with
// the EWA splat renderer and VTK's CPU ray caster timed on the same views in the same run.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/scene.h"
#include "bench/bench_support.h"
#include "bench/vtk_runner.h"
#include "core/shear_warp.h"
#include "gl/shader_library.h"
#include "platform/headless_context.h"
#include "render/splat_renderer.h"

namespace ewa {
namespace {

struct Variant {
  const char* name;
  ShearWarpSettings settings;
};

// Table 1's columns: standard (no correction), then pre-integration with nearest/bilinear
// lookup, without/with opacity correction, slice-/image-sized buffers; and standard with
// correction (ewaview's default) for reference.
std::vector<Variant> variants(int threads) {
  std::vector<Variant> v;
  auto make = [&](const char* name, bool pre, TableLookup lookup, bool oc, BufferSlices b) {
    ShearWarpSettings s;
    s.preintegrated = pre;
    s.lookup = lookup;
    s.opacityCorrection = oc;
    s.buffers = b;
    s.threads = threads;
    s.intermediateScale = 1.0;  // the paper's one intermediate pixel a voxel
    v.push_back({name, s});
  };
  const auto N = TableLookup::Nearest, B = TableLookup::Bilinear;
  const auto SB = BufferSlices::Slice, IB = BufferSlices::Image;
  make("std", false, N, false, SB);
  make("nn-nc-sb", true, N, false, SB);
  make("nn-nc-ib", true, N, false, IB);
  make("nn-oc-sb", true, N, true, SB);
  make("nn-oc-ib", true, N, true, IB);
  make("bl-nc-sb", true, B, false, SB);
  make("bl-nc-ib", true, B, false, IB);
  make("bl-oc-sb", true, B, true, SB);
  make("bl-oc-ib", true, B, true, IB);
  make("std-oc", false, N, true, SB);
  return v;
}

// The paper's performance transfer function: opacity ramps linearly from 0 to 1 over the
// whole data range (per smallest spacing), colour from dark red to white.
TransferFunction rampTf(const Volume& v) {
  TransferFunction tf;
  const double lo = v.minValue(), hi = v.maxValue();
  tf.opacity = {{lo, 0.0}, {hi, 1.0}};
  tf.color = {{lo, {0.6, 0.1, 0.05}}, {hi, {1.0, 1.0, 1.0}}};
  const glm::dvec3 s = v.spacing();
  tf.opacityUnitDistance = std::min({s.x, s.y, s.z});
  return tf;
}

double transparentPercent(const Volume& v, const TransferFunction& tf) {
  int64_t clear = 0;
  for (int64_t n = 0; n < v.voxelCount(); ++n) clear += tf.alphaAt(v.valueAt(n)) <= 0.0;
  return 100.0 * double(clear) / double(v.voxelCount());
}

// VTK's ray caster through scripts/vtk_raycast_bench.py: (wall, CPU) seconds per frame, or
// negative when it could not run.
glm::dvec2 timeVtk(const Volume& v, const TransferFunction& tf, int size,
                   const std::vector<double>& azimuths, const std::string& script) {
  std::string views;
  for (double a : azimuths) views += (views.empty() ? "" : ",") + std::to_string(a);
  const VtkTiming t =
      VtkRunner(v, tf, script).run({"--size", std::to_string(size), "--views", views});
  if (!t.ok) {
    std::fprintf(stderr, "# VTK not timed: %s\n", t.error.c_str());
    return glm::dvec2(-1.0);
  }
  return glm::dvec2(t.meanSeconds, t.cpuSeconds);
}

int run(int argc, char** argv) {
  CLI::App app{
      "ewaview-shearwarp-bench: shear-warp variants (Table 1 of Schulze et al. 2003), "
      "EWA splatting and VTK's CPU ray caster on the same turntable views"};
  std::string data = sharedDataDir();
  int size = 512, frames = 90, every = 1, ewaViews = 1, threads = 0;
  double step = 2.0;
  bool noVtk = false, noEwa = false, breakdown = false;
  std::vector<std::string> only;
  std::string script = VtkRunner::defaultScript();
  app.add_option("--data", data,
                 "Folder with engine/, mrbrain/ and bonsai/ (default ../shared/data)");
  app.add_option("--volumes", only, "Subset of engine, mrbrain, bonsai");
  app.add_option("--size", size, "Image width and height (default 512)")
      ->check(CLI::Range(16, 4096));
  app.add_option("--frames", frames, "Turntable views (default 90: 180 degrees)")
      ->check(CLI::Range(1, 3600));
  app.add_option("--step", step, "Degrees between views (default 2)");
  app.add_option("--every", every, "Time every n-th view only (default 1: all)")
      ->check(CLI::Range(1, 3600));
  app.add_option("--ewa-views", ewaViews,
                 "Views the EWA renderer is timed on, spread over the timed ones (default 1)");
  app.add_option("--threads", threads, "Shear-warp threads (default: all)");
  app.add_flag("--no-vtk", noVtk, "Do not time VTK");
  app.add_flag("--breakdown", breakdown,
               "Also print table/composite/warp milliseconds per variant");
  app.add_flag("--no-ewa", noEwa, "Do not time the EWA splat renderer");
  app.add_option("--vtk-script", script, "Path of vtk_raycast_bench.py");
  CLI11_PARSE(app, argc, argv);

  struct Input {
    std::string name;
    Options options;
  };
  std::vector<Input> inputs(3);
  inputs[0].name = "engine";
  inputs[0].options.file = data + "/engine/engine.nhdr";
  inputs[1].name = "mrbrain";
  inputs[1].options.file = data + "/mrbrain/MRbrain.raw";
  inputs[1].options.rawDims = "256,256,109";
  inputs[1].options.rawType = "uint16";
  inputs[1].options.rawSpacing = "1,1,2";
  inputs[1].options.rawEndian = "big";
  inputs[2].name = "bonsai";
  inputs[2].options.file = data + "/bonsai/bonsai.nhdr";
  if (!only.empty())
    inputs.erase(std::remove_if(inputs.begin(), inputs.end(),
                                [&](const Input& i) {
                                  return std::find(only.begin(), only.end(), i.name) == only.end();
                                }),
                 inputs.end());

  std::unique_ptr<platform::GlContext> context;
  std::unique_ptr<SplatRenderer> splat;
  if (!noEwa) {
    context = platform::createHeadlessContext(platform::HeadlessBackend::OsMesa);
    splat = std::make_unique<SplatRenderer>(gl::ShaderLibrary());
  }
  const std::vector<Variant> vs = variants(threads);
  std::printf(
      "# %dx%d, parallel projection, %d views of %.1f deg (every %d-th timed), %d shear-warp "
      "threads\n",
      size, size, frames, step, every, shearWarpThreads(vs[0].settings));
  std::printf(
      "# wall seconds per frame (mean), then CPU seconds (all threads); ewa and vtk on [n] "
      "views;\n# table = pre-integration table build (ms); ratios pre/std and std/vtk from CPU "
      "time\n");
  std::printf("%-8s %-12s %6s |", "volume", "dims", "clear%");
  for (const Variant& v : vs) std::printf(" %8s", v.name);
  std::printf(" | %11s %11s | %6s | %s\n", "ewa", "vtk", "table", "pre/std  std/vtk");
  for (Input& in : inputs) {
    in.options.width = in.options.height = size;
    in.options.orthographic = true;
    Scene scene;
    try {
      scene = loadScene(in.options);
    } catch (const std::exception& e) {
      std::printf("%-8s skipped: %s\n", in.name.c_str(), e.what());
      continue;
    }
    const Volume& vol = scene.volume;
    const TransferFunction tf = rampTf(vol);
    ShearWarp sw;
    sw.setVolume(vol);
    sw.setTransferFunction(tf);
    Camera cam = initialCamera(vol, in.options);
    std::vector<Camera> views;
    std::vector<double> azimuths;
    for (int f = 0; f < frames; ++f) {
      if (f % every == 0) {
        views.push_back(cam);
        azimuths.push_back(f * step);
      }
      cam.orbit(step, 0.0);
    }
    sw.prepareAllAxes();  // volume preparation, not timed
    sw.render(views[0], vs[1].settings, size, size);
    const double tableMs = [&] {
      const auto t = BenchClock::now();
      PreintegrationTable::build(tf, vol.minValue(), vol.maxValue(), 256, vol.spacing().x);
      return secondsSince(t) * 1e3;
    }();
    // Every variant renders each view in turn, so load changes on the machine hit all alike.
    std::vector<double> total(vs.size(), 0.0), cpu(vs.size(), 0.0);
    std::vector<glm::dvec3> parts(vs.size(), glm::dvec3(0.0));  // table, composite, warp ms
    for (const Camera& c : views)
      for (size_t i = 0; i < vs.size(); ++i) {
        const auto t = BenchClock::now();
        const double c0 = cpuSeconds();
        sw.render(c, vs[i].settings, size, size);
        total[i] += secondsSince(t);
        cpu[i] += cpuSeconds() - c0;
        const ShearWarpStats& st = sw.stats();
        parts[i] += glm::dvec3(st.tableMs, st.compositeMs, st.warpMs);
      }
    double ewa = -1.0;
    int ewaCount = 0;
    if (splat && ewaViews > 0) {
      RenderSettings rs;
      splat->setVolume(vol);
      splat->setTransferFunction(tf);
      splat->render(views[0], rs, size, size);  // upload, not timed
      double sum = 0.0;
      const int n = std::min<int>(ewaViews, int(views.size()));
      for (int e = 0; e < n; ++e) {
        splat->render(views[size_t(e) * views.size() / n], rs, size, size);
        sum += splat->stats().renderMs / 1e3;
      }
      ewa = sum / n;
      ewaCount = n;
    }
    const glm::dvec2 vtkTimes = noVtk ? glm::dvec2(-1.0) : timeVtk(vol, tf, size, azimuths, script);
    const double vtk = vtkTimes.x;
    const auto& d = vol.dims();
    char dims[32];
    std::snprintf(dims, sizeof dims, "%lldx%lldx%lld", (long long)d[0], (long long)d[1],
                  (long long)d[2]);
    std::printf("%-8s %-12s %6.1f |", in.name.c_str(), dims, transparentPercent(vol, tf));
    double preMin = 1e30, preMax = 0.0;
    for (size_t i = 0; i < vs.size(); ++i) {
      std::printf(" %8.3f", total[i] / views.size());
      // Ratios from CPU time, which other programs on the machine disturb less.
      if (vs[i].settings.preintegrated) {
        preMin = std::min(preMin, cpu[i] / cpu[0]);
        preMax = std::max(preMax, cpu[i] / cpu[0]);
      }
    }
    const double standardCpu = cpu[0] / views.size();
    char ewaText[32] = "-", vtkText[32] = "-";
    if (ewa >= 0) std::snprintf(ewaText, sizeof ewaText, "%.2f [%d]", ewa, ewaCount);
    if (vtk >= 0) std::snprintf(vtkText, sizeof vtkText, "%.3f [%zu]", vtk, views.size());
    std::printf(" | %11s %11s | %6.1f | %.2f-%.2f", ewaText, vtkText, tableMs, preMin, preMax);
    if (vtkTimes.y > 0) std::printf("  1/%.1f", vtkTimes.y / standardCpu);
    std::printf("\n%-8s %-12s %6s |", "  cpu s", "", "");
    for (size_t i = 0; i < vs.size(); ++i) std::printf(" %8.3f", cpu[i] / views.size());
    std::printf(" | %11s %11.3f |\n", "", vtkTimes.y);
    if (breakdown)
      for (size_t i = 0; i < vs.size(); ++i) {
        const glm::dvec3 p = parts[i] / double(views.size());
        std::printf("#   %-8s table %.1f ms, composite %.1f ms, warp %.1f ms\n", vs[i].name, p.x,
                    p.y, p.z);
      }
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace
}  // namespace ewa

int main(int argc, char** argv) {
  return ewa::benchmarkMain("ewaview-shearwarp-bench", ewa::run, argc, argv);
}
