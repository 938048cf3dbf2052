// ewaview-compare: the same view, transfer function and image size drawn by EWA splatting (full
// frame and its stages), bare point sprites, shear-warp and VTK's CPU and GPU ray casters, in
// one run, with the ratios the performance targets are stated in.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "app/frame_stats.h"
#include "app/options.h"
#include "app/scene.h"
#include "bench/bench_sprites.h"
#include "bench/bench_support.h"
#include "bench/bench_tile_ewa.h"
#include "bench/compare_options.h"
#include "bench/compare_report.h"
#include "bench/sprite_baseline.h"
#include "bench/tile_splat_baseline.h"
#include "bench/vtk_runner.h"
#include "gl/gl_api.h"
#include "gl/shader_library.h"
#include "io/png_io.h"
#include "platform/headless_context.h"
#include "render/cpu_splatter.h"
#include "render/renderer_factory.h"
#include "render/splat_renderer.h"
#include "render/tile_ewa_splatter.h"

namespace ewa {
namespace {

struct Input {
  std::string name;
  Options options;  // file or synthetic, and the transfer function
};

// The shared volumes the targets name, with the transfer functions the presets give them
// (engine has none: the histogram's, as ewaview opens it).
std::vector<Input> sharedInputs(const std::string& data, const std::vector<std::string>& only) {
  const std::string presets = std::string(EWA_ASSET_DIR) + "/presets/";
  std::vector<Input> all(3);
  all[0].name = "engine";
  all[0].options.file = data + "/engine/engine.nhdr";
  all[1].name = "bonsai";
  all[1].options.file = data + "/bonsai/bonsai.nhdr";
  all[1].options.tfFile = presets + "bonsai.tf.json";
  all[2].name = "cthead";
  all[2].options.file = data + "/cthead/CThead.nhdr";
  all[2].options.tfFile = presets + "cthead_skull.tf.json";
  std::vector<Input> out;
  for (const Input& in : all)
    if (std::find(only.begin(), only.end(), in.name) != only.end()) out.push_back(in);
  return out;
}

std::string dimsText(const Volume& v) {
  const auto& d = v.dims();
  return std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]);
}

// "marschner-lobb:64" -> "marschner-lobb-64": a volume's name as part of a file name.
std::string fileName(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '-';
  return name;
}

struct Methods {
  SplatRenderer& ewa;
  SpriteBaseline& sprites;
  TileSplatBaseline& tiles;
  TileEwaSplatter& tileEwa;
  Renderer& shearWarp;
  Image8& cpuPicture;  // the CPU splatter's last picture (cpu_ms), where it drew the frame
  // Methods --skip leaves out (their columns stay '-'): the compute tiles take seconds a frame
  // on a software rasterizer, the default post-classified frame in tiles tens of seconds.
  std::set<std::string> skip;
  bool timed(const char* method) const { return skip.count(method) == 0; }
};

// Times EWA, sprites and shear-warp on one view: a warm-up frame each, then `repeats` rounds
// in which each draws once, so load changes on the machine hit all three alike.
void timeOpenGlMethods(Methods m, const Scene& scene, const Camera& cam, const RenderSettings& rs,
                       int size, int repeats, CompareRow& row) {
  m.ewa.render(cam, rs, size, size);  // warm-up: classification and upload, not timed
  glFinish();
  const bool sprites = m.timed("sprites"), tiles = m.timed("tiles"),
             shearWarp = m.timed("shearwarp");
  if (sprites) {
    m.sprites.setSprites(spriteSizes(m.ewa, scene.volume, cam, rs, size, size));
    m.sprites.draw(size, size, halfFloatSlabs(rs));
  }
  if (tiles) {
    m.tiles.setFootprints(tileFootprints(m.ewa, scene.volume, cam, rs, size, size),
                          float(rs.cutoff));
    m.tiles.draw(size, size, halfFloatSlabs(rs));
  }
  // The compute EWA splatter draws front-to-back frames, pre-classified or post-classified as the
  // default (SplatRenderer::tileComposite), from 64 bytes a splat: up to 8 M splats (a 512^3
  // volume's 74 M would take 4.7 GB twice over), and only as many as one storage block holds. It
  // draws the renderer's last frame as the renderer's own tile frames do (SplatRenderer::loadTiles,
  // timed with the tiles): its slab lists binned where the GPU built them (their making is in
  // partition_ms), else the CPU partition's uploaded; its records made on the GPU; the
  // classification's state set.
  bool post = false, shading = false;
  const bool tileEwa = m.timed("tile-ewa") && m.ewa.tileComposite(post, shading) &&
                       m.ewa.splats().size() <= size_t(8'000'000) && m.ewa.tileRecordsFit();
  const auto tileEwaDraw = [&] {
    const auto start = BenchClock::now();
    m.ewa.loadTiles(m.tileEwa);
    glFinish();
    return millisecondsSince(start) + m.tileEwa.draw(size, size).totalMs();
  };
  if (tileEwa) tileEwaDraw();  // warm-up: the programs' first use
  // The same frame splatted on the CPU by the same renderer (Splatter::Cpu): before the
  // rasterized frame of each round, so the renderer's statistics and picture stay the
  // rasterized frame's.
  RenderSettings cpuSettings = rs;
  cpuSettings.splatter = Splatter::Cpu;
  const bool cpu = m.timed("cpu");
  std::vector<double> cpuPartition, cpuRecords, cpuBins, cpuTiles;
  const auto cpuDraw = [&] {
    const auto start = BenchClock::now();
    m.ewa.render(cam, cpuSettings, size, size);
    glFinish();
    const double ms = millisecondsSince(start);
    const RenderStats& c = m.ewa.stats();
    cpuPartition.push_back(c.partitionMs);
    cpuRecords.push_back(c.cpuRecordsMs);
    cpuBins.push_back(c.cpuBinMs);
    cpuTiles.push_back(c.cpuTilesMs);
    row.cpuBytesPerSplat = cpuBytesPerSplat(c);
    m.cpuPicture = m.ewa.readImage();
    return ms;
  };
  if (cpu) {
    cpuDraw();  // warm-up: its buffers
    cpuPartition.clear();
    cpuRecords.clear();
    cpuBins.clear();
    cpuTiles.clear();
  }
  RenderSettings sw = rs;
  sw.renderer = RendererKind::ShearWarp;
  if (shearWarp) m.shearWarp.render(cam, sw, size, size);
  std::vector<double> ewa, partition, splat, final, spriteMs, tileMs, tileBins, tileEwaMs,
      shearWarpMs, cpuMs;
  for (int r = 0; r < repeats; ++r) {
    if (cpu) cpuMs.push_back(cpuDraw());
    auto start = BenchClock::now();
    m.ewa.render(cam, rs, size, size);
    glFinish();
    ewa.push_back(millisecondsSince(start));
    const RenderStats s = m.ewa.stats();
    partition.push_back(s.partitionMs);
    splat.push_back(s.splatMs);
    final.push_back(s.compositeMs);
    if (sprites) spriteMs.push_back(m.sprites.draw(size, size, halfFloatSlabs(rs)));
    if (tiles) {
      const TileSplatBaseline::Timing t = m.tiles.draw(size, size, halfFloatSlabs(rs));
      tileMs.push_back(t.totalMs());
      tileBins.push_back(t.binMs);
    }
    if (tileEwa) tileEwaMs.push_back(tileEwaDraw());
    if (shearWarp) {
      start = BenchClock::now();
      m.shearWarp.render(cam, sw, size, size);
      glFinish();
      shearWarpMs.push_back(millisecondsSince(start));
    }
  }
  const RenderStats s = m.ewa.stats();
  row.splats = s.splatsTotal;
  row.splatsDrawn = s.splatsDrawn;
  row.slabEntries = s.slabEntries;
  row.entriesCulled = s.entriesCulled;
  row.gpuBytes = s.gpuBytes;
  row.gpuBytesPerSplat = gpuBytesPerSplat(s);
  const TimingSummary e = summarize(ewa);
  row.ewaMs = e.median;
  row.ewaMinMs = e.min;
  row.partitionMs = summarize(partition).median;
  row.splatMs = summarize(splat).median;
  row.finalMs = summarize(final).median;
  if (sprites) row.spritesMs = summarize(spriteMs).median;
  if (tiles) {
    row.tilesMs = summarize(tileMs).median;
    row.tilesBinMs = summarize(tileBins).median;
  }
  if (tileEwa) row.tileEwaMs = summarize(tileEwaMs).median;
  if (cpu) {
    row.cpuMs = summarize(cpuMs).median;
    row.cpuPartitionMs = summarize(cpuPartition).median;
    row.cpuRecordsMs = summarize(cpuRecords).median;
    row.cpuBinMs = summarize(cpuBins).median;
    row.cpuTilesMs = summarize(cpuTiles).median;
  }
  if (shearWarp) row.shearWarpMs = summarize(shearWarpMs).median;
}

int run(int argc, char** argv) {
  CLI::App app{
      "ewaview-compare: EWA splatting beside bare point sprites, shear-warp and VTK's CPU and "
      "GPU ray casters on the same views (median ms per frame and ratios)"};
  CompareOptions o;
  addCompareOptions(app, o);
  CLI11_PARSE(app, argc, argv);
  applyCompareOptions(o);

  CompareReport report;
  report.repeats = o.repeats;
  for (int i = 0; i < argc; ++i) report.command += (i ? " " : "") + std::string(argv[i]);
  std::vector<Input> inputs = sharedInputs(o.data, o.volumes);
  for (const std::string& spec : o.synthetic) {
    Input in;
    in.name = spec;
    in.options.synthetic = spec;
    inputs.push_back(in);
  }
  if (!o.imagesDir.empty()) std::filesystem::create_directories(o.imagesDir);

  auto context = platform::createHeadlessContext(platform::parseHeadlessBackend(o.backend));
  // The cores the CPU splatter and VTK's CPU ray caster spread over.
  report.context = context->description() + "; " +
                   std::to_string(std::thread::hardware_concurrency()) + " CPU cores";
  const std::set<std::string> skipped(o.skip.begin(), o.skip.end());
  const gl::ShaderLibrary shaders(o.shaderDir);
  SplatRenderer ewa(shaders);
  ewa.setSlabScissor(o.slabRects == "on");
  PartitionMode partitionMode = PartitionMode::Auto;
  parsePartitionMode(o.partition, &partitionMode);
  ewa.setPartition(partitionMode);
  report.ewaSettings =
      ewaSettingsText(o, ewa.occlusionCulling(o.settings.occlusionCulling), ewa.gpuPartition());
  SpriteBaseline sprites(shaders);
  TileSplatBaseline tiles(shaders, o.tileSize);
  TileEwaSplatter tileEwa(shaders, o.tileSize);
  Image8 cpuPicture;
  const std::unique_ptr<Renderer> shearWarp = createRenderer(RendererKind::ShearWarp, shaders);
  bool vtkWorks = !o.noVtk, failed = false;
  for (Input& in : inputs) {
    if (!in.options.file.empty() && !std::filesystem::exists(in.options.file)) {
      const std::string note = in.name + " skipped: " + in.options.file + " not found";
      std::cerr << "ewaview-compare: " << note << "\n";
      report.notes.push_back(note);
      continue;
    }
    in.options.orthographic = o.orthographic;
    in.options.render = o.settings;
    const Scene scene = loadScene(in.options);
    ewa.setVolume(scene.volume);
    ewa.setTransferFunction(scene.transferFunction);
    shearWarp->setVolume(scene.volume);
    shearWarp->setTransferFunction(scene.transferFunction);
    std::unique_ptr<VtkRunner> vtk;
    if (vtkWorks) vtk = std::make_unique<VtkRunner>(scene.volume, scene.transferFunction, o.script);
    for (int size : o.sizes) {
      in.options.width = in.options.height = size;
      const Camera cam = initialCamera(scene.volume, in.options);
      const RenderSettings rs = in.options.render;
      CompareRow row;
      row.volume = in.name;
      row.dims = dimsText(scene.volume);
      row.size = size;
      try {
        timeOpenGlMethods({ewa, sprites, tiles, tileEwa, *shearWarp, cpuPicture, skipped}, scene,
                          cam, rs, size, o.repeats, row);
      } catch (const std::exception& e) {
        // Too big for this GL (the splat buffer's limit): the other volumes still run.
        const std::string note =
            in.name + " " + std::to_string(size) + " not measured: " + e.what();
        std::cerr << "ewaview-compare: " << note << "\n";
        report.notes.push_back(note);
        failed = true;
        break;
      }
      if (rs.slabPasses == 0 && ewa.stats().slabPasses == 2)
        report.notes.push_back(in.name + " " + std::to_string(size) +
                               ": EWA's last frames took 2 passes a slab (auto, timed faster)");
      const std::string stem =
          o.imagesDir + "/" + fileName(in.name) + "_" + std::to_string(size) + "_";
      if (!o.imagesDir.empty()) {
        writePng(stem + "ewa.png", ewa.readImage());
        if (row.shearWarpMs >= 0) writePng(stem + "shearwarp.png", shearWarp->readImage());
        if (row.tileEwaMs >= 0)
          writePng(stem + "tile-ewa.png",
                   tileEwaImage(tileEwa.picture(), size, size, rs.background));
        if (row.cpuMs >= 0) writePng(stem + "cpu.png", cpuPicture);
      }
      for (const char* mapper : {"cpu", "gpu"}) {
        if (!vtkWorks) break;
        std::vector<std::string> args = vtkCameraArguments(cam, scene.volume);
        args.insert(args.end(), {"--size", std::to_string(size), "--repeats",
                                 std::to_string(o.repeats), "--mapper", mapper});
        const std::vector<std::string> light = vtkLightingArguments(rs.lighting);
        args.insert(args.end(), light.begin(), light.end());
        if (!o.imagesDir.empty())
          args.insert(args.end(), {"--image", stem + "vtk-" + mapper + ".png"});
        const VtkTiming t = vtk->run(args);
        if (!t.ok) {
          // No VTK or no display: say so once and time the rest.
          report.notes.push_back(std::string("VTK not timed: ") + t.error);
          std::cerr << "ewaview-compare: VTK not timed: " << t.error << "\n";
          vtkWorks = false;
          break;
        }
        (std::string(mapper) == "cpu" ? row.vtkCpuMs : row.vtkGpuMs) = t.medianSeconds * 1e3;
      }
      row.peakRss = peakRssBytes();
      report.rows.push_back(row);
      std::cerr << "ewaview-compare: " << in.name << " " << size << ": EWA " << row.ewaMs
                << " ms\n";
    }
  }
  printReport(std::cout, report,
              o.json  ? ReportFormat::Json
              : o.csv ? ReportFormat::Csv
                      : ReportFormat::Table);
  return failed ? 1 : 0;
}

}  // namespace
}  // namespace ewa

int main(int argc, char** argv) {
  return ewa::benchmarkMain("ewaview-compare", ewa::run, argc, argv);
}
