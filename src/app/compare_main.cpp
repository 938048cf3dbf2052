// ewaview-compare: the same view, transfer function and image size drawn by EWA splatting (full
// frame and its stages), bare point sprites, shear-warp and VTK's CPU and GPU ray casters, in
// one run, with the ratios the performance targets are stated in.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "app/bench_sprites.h"
#include "app/bench_support.h"
#include "app/bench_tile_ewa.h"
#include "app/compare_report.h"
#include "app/frame_stats.h"
#include "app/options.h"
#include "app/scene.h"
#include "app/vtk_runner.h"
#include "core/kernel_lattice.h"
#include "core/post_classification.h"
#include "gl/gl_api.h"
#include "gl/shader_library.h"
#include "io/png_io.h"
#include "platform/headless_context.h"
#include "render/renderer_factory.h"
#include "render/splat_renderer.h"
#include "render/sprite_baseline.h"
#include "render/tile_ewa_splatter.h"
#include "render/tile_splat_baseline.h"

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
  // volume's 74 M would take 4.7 GB twice over). It draws the renderer's last frame as the
  // renderer's own tile frames do (SplatRenderer::loadTiles, timed with the tiles): its slab
  // lists binned where the GPU built them (their making is in partition_ms), else the CPU
  // partition's uploaded; its records made on the GPU; the classification's state set.
  bool post = false, shading = false;
  const bool tileEwa = m.timed("tile-ewa") && m.ewa.tileComposite(post, shading) &&
                       m.ewa.splats().size() <= size_t(8'000'000);
  const auto tileEwaDraw = [&] {
    const auto start = BenchClock::now();
    m.ewa.loadTiles(m.tileEwa);
    glFinish();
    return millisecondsSince(start) + m.tileEwa.draw(size, size).totalMs();
  };
  if (tileEwa) tileEwaDraw();  // warm-up: the programs' first use
  RenderSettings sw = rs;
  sw.renderer = RendererKind::ShearWarp;
  if (shearWarp) m.shearWarp.render(cam, sw, size, size);
  std::vector<double> ewa, partition, splat, final, spriteMs, tileMs, tileBins, tileEwaMs,
      shearWarpMs;
  for (int r = 0; r < repeats; ++r) {
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
  if (shearWarp) row.shearWarpMs = summarize(shearWarpMs).median;
}

int run(int argc, char** argv) {
  CLI::App app{
      "ewaview-compare: EWA splatting beside bare point sprites, shear-warp and VTK's CPU and "
      "GPU ray casters on the same views (median ms per frame and ratios)"};
  std::string data = sharedDataDir(), imagesDir, backend = "osmesa", shaderDir;
  std::string script = VtkRunner::defaultScript();
  std::vector<std::string> volumes, synthetic;
  std::vector<int> sizes = {512, 1024};
  int repeats = 5;
  bool csv = false, json = false, noVtk = false, orthographic = false;
  RenderSettings settings;  // EWA's: the defaults unless --kernel-width, --cutoff, ...
  // The EWA column is the rasterized frame; the tile_ewa column times the tiles beside it.
  settings.splatter = Splatter::Raster;
  std::string classification = classificationModeName(settings.classification.mode),
              culling = "auto", slabRects = "on", pairs = "on", slabResolution = "auto",
              slabPrecision = "auto", partition = "auto";
  app.add_option("--data", data,
                 "Folder with engine/, bonsai/ and cthead/ (default ../shared/data)");
  app.add_option("--volumes", volumes,
                 "Subset of engine, bonsai, cthead (default: all three, none with --synthetic)")
      ->delimiter(',')
      ->check(CLI::IsMember({"engine", "bonsai", "cthead"}));
  app.add_option("--synthetic", synthetic,
                 "Also a synthetic volume NAME:N as ewaview --synthetic makes it (repeatable)");
  app.add_option("--sizes", sizes, "Image sizes (width = height; default 512,1024)")
      ->delimiter(',')
      ->check(CLI::Range(16, 4096));
  app.add_option("--repeats", repeats, "Timed frames per method after a warm-up (default 5)")
      ->check(CLI::Range(1, 1000));
  app.add_flag("--csv", csv, "Print CSV instead of the table");
  app.add_flag("--json", json, "Print one JSON document instead of the table")->excludes("--csv");
  app.add_option("--images", imagesDir,
                 "Save each method's picture as DIR/VOLUME_SIZE_METHOD.png, to compare by eye");
  app.add_flag("--no-vtk", noVtk, "Do not time VTK's ray casters");
  std::vector<std::string> skip;
  app.add_option("--skip", skip,
                 "Methods not to time, their columns left '-': sprites, tiles (tiles_ms), "
                 "tile-ewa (tile_ewa_ms), shearwarp")
      ->delimiter(',')
      ->check(CLI::IsMember({"sprites", "tiles", "tile-ewa", "shearwarp"}));
  app.add_option("--vtk-script", script, "Path of vtk_raycast_bench.py");
  app.add_flag("--orthographic", orthographic, "Parallel projection (default: perspective)");
  app.add_option("--kernel-width", settings.kernelWidth,
                 "EWA kernel sigma in voxel spacings, 0.3 to 2 (default 0.7)")
      ->check(CLI::Range(kMinKernelWidth, kMaxKernelWidth));
  app.add_option("--cutoff", settings.cutoff, "EWA footprint cutoff r = dx^T Q dx (default 5)")
      ->check(CLI::Range(0.25, 64.0));
  app.add_option("--depth-cutoff", settings.depthCutoff,
                 "EWA kernels' depth extent in squared sigmas, or inf (default 1)")
      ->check(CLI::Range(0.25, double(INFINITY)));
  app.add_option("--classification", classification,
                 "EWA: transfer function per pixel (post, default) or per voxel (pre)")
      ->check(CLI::IsMember({"pre", "post"}));
  app.add_option("--slab-preintegration", pairs,
                 "EWA post-classification: slab value pairs through the pre-integration table "
                 "(on, default) or each slab's value alone (off)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--slab-samples", settings.slabSamples,
                 "EWA post-classification, pre-integrated: depth samples a slab, 4 (default) or 2")
      ->check(CLI::IsMember({2, 4}));
  app.add_option("--slab-thickness", settings.slabThickness,
                 "EWA: slab thickness in voxels of the smallest spacing (default 2)")
      ->check(CLI::Range(0.25, 1000.0));
  std::string slabPasses = "auto";
  app.add_option("--slab-passes", slabPasses,
                 "EWA, 4 samples a slab: splat each slab once into both images (1) or once into "
                 "each (2); auto (default): 1 on software rasterizers, else the faster as timed")
      ->check(CLI::IsMember({"auto", "1", "2"}));
  app.add_option("--prefilter", settings.classification.prefilter,
                 "EWA post-classification: value prefilter strength (default 0.04)")
      ->check(CLI::Range(0.0, kMaxPrefilter));
  app.add_option("--occlusion-culling", culling,
                 "EWA: occlusion culling auto (default: off on software rasterizers), on or off")
      ->check(CLI::IsMember({"auto", "on", "off"}));
  app.add_option("--slab-rects", slabRects,
                 "EWA: each slab's passes cut to the pixels its kernels reach (on, default) or "
                 "over the whole image (off)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--slab-resolution", slabResolution,
                 "EWA: slabs splatted into images as coarse as their kernels allow (auto, "
                 "default) or at full resolution (full)")
      ->check(CLI::IsMember({"auto", "full"}));
  app.add_option("--slab-precision", slabPrecision,
                 "EWA: slab images of half floats (half) or floats (float); auto (default): "
                 "half for kernel widths up to 1 unless shaded and post-classified. The bare "
                 "sprites draw into the same")
      ->check(CLI::IsMember({"auto", "half", "float"}));
  app.add_option("--partition", partition,
                 "EWA: where the slab partition is built: auto (default: the CPU on software "
                 "rasterizers, the GPU elsewhere), gpu or cpu")
      ->check(CLI::IsMember({"auto", "gpu", "cpu"}));
  bool shading = false;
  std::string postNormals = "ray";
  app.add_flag("--shading", shading, "EWA: Phong shading with a head light");
  app.add_option("--post-normals", postNormals,
                 "EWA post-classified, with --shading: field, voxel or ray (default) normals")
      ->check(CLI::IsMember({"field", "voxel", "ray"}));
  int tileSize = 16;
  app.add_option("--tile-size", tileSize,
                 "Pixels a side of the compute tiles of the tiles_ms and tile_ewa_ms columns (8 or "
                 "16, default 16)")
      ->check(CLI::IsMember({8, 16}));
  app.add_option("--shader-dir", shaderDir, "Load shaders from this folder (development)");
  addBackendOption(app, backend);
  CLI11_PARSE(app, argc, argv);
  if (volumes.empty() && synthetic.empty()) volumes = {"engine", "bonsai", "cthead"};
  parseClassificationMode(classification, &settings.classification.mode);
  parseOcclusionCulling(culling, &settings.occlusionCulling);
  settings.slabPreintegration = pairs == "on";
  settings.coarseSlabs = slabResolution == "auto";
  parseSlabPrecision(slabPrecision, &settings.slabPrecision);
  parseSlabPasses(slabPasses, &settings.slabPasses);
  settings.lighting.enabled = shading;
  parsePostNormals(postNormals, &settings.postNormals);

  CompareReport report;
  report.repeats = repeats;
  for (int i = 0; i < argc; ++i) report.command += (i ? " " : "") + std::string(argv[i]);
  std::vector<Input> inputs = sharedInputs(data, volumes);
  for (const std::string& spec : synthetic) {
    Input in;
    in.name = spec;
    in.options.synthetic = spec;
    inputs.push_back(in);
  }
  if (!imagesDir.empty()) std::filesystem::create_directories(imagesDir);

  auto context = platform::createHeadlessContext(platform::parseHeadlessBackend(backend));
  report.context = context->description();
  const std::set<std::string> skipped(skip.begin(), skip.end());
  if (!orthographic && skipped.count("shearwarp") == 0)
    report.notes.push_back("shear-warp draws the perspective view as the parallel one");
  const gl::ShaderLibrary shaders(shaderDir);
  SplatRenderer ewa(shaders);
  ewa.setSlabScissor(slabRects == "on");
  PartitionMode partitionMode = PartitionMode::Auto;
  parsePartitionMode(partition, &partitionMode);
  ewa.setPartition(partitionMode);
  const std::string shadingText =
      !shading ? ""
      : classification == "pre"
          ? ", shaded"
          : std::string(", shaded with ") + postNormalsName(settings.postNormals) + " normals";
  char ewaText[480], prefilterText[64];
  std::snprintf(prefilterText, sizeof prefilterText, ", prefilter %g%s",
                settings.classification.prefilter,
                pairs == "on" ? (settings.slabSamples < 4   ? ", 2 samples a slab"
                                 : settings.slabPasses == 0 ? ", 4 samples a slab"
                                 : settings.slabPasses == 1 ? ", 4 samples a slab in 1 pass"
                                                            : ", 4 samples a slab in 2 passes")
                              : "");
  std::snprintf(
      ewaText, sizeof ewaText,
      "kernel width %.2f, cutoff %g, depth cutoff %g, slabs %g thick, "
      "%s-classification%s%s, %s slab images, occlusion culling %s%s%s%s, "
      "slab partition on the %s%s%s",
      settings.kernelWidth, settings.cutoff, settings.depthCutoff, settings.slabThickness,
      classification.c_str(),
      classification == "post" && pairs == "off" ? " without slab pre-integration" : "",
      classification == "post" ? prefilterText : "",
      halfFloatSlabs(settings) ? "half-float" : "float",
      ewa.occlusionCulling(settings.occlusionCulling) ? "on" : "off",
      culling == "auto" ? " (auto)" : "", slabRects == "on" ? "" : ", whole-image slab passes",
      slabResolution == "auto" ? "" : ", full-resolution slabs", ewa.gpuPartition() ? "GPU" : "CPU",
      partition == "auto" ? " (auto)" : "", shadingText.c_str());
  report.ewaSettings = ewaText;
  SpriteBaseline sprites(shaders);
  TileSplatBaseline tiles(shaders, tileSize);
  TileEwaSplatter tileEwa(shaders, tileSize);
  const std::unique_ptr<Renderer> shearWarp = createRenderer(RendererKind::ShearWarp, shaders);
  bool vtkWorks = !noVtk, failed = false;
  for (Input& in : inputs) {
    if (!in.options.file.empty() && !std::filesystem::exists(in.options.file)) {
      const std::string note = in.name + " skipped: " + in.options.file + " not found";
      std::cerr << "ewaview-compare: " << note << "\n";
      report.notes.push_back(note);
      continue;
    }
    in.options.orthographic = orthographic;
    in.options.render = settings;
    const Scene scene = loadScene(in.options);
    ewa.setVolume(scene.volume);
    ewa.setTransferFunction(scene.transferFunction);
    shearWarp->setVolume(scene.volume);
    shearWarp->setTransferFunction(scene.transferFunction);
    std::unique_ptr<VtkRunner> vtk;
    if (vtkWorks) vtk = std::make_unique<VtkRunner>(scene.volume, scene.transferFunction, script);
    for (int size : sizes) {
      in.options.width = in.options.height = size;
      const Camera cam = initialCamera(scene.volume, in.options);
      const RenderSettings rs = in.options.render;
      CompareRow row;
      row.volume = in.name;
      row.dims = dimsText(scene.volume);
      row.size = size;
      try {
        timeOpenGlMethods({ewa, sprites, tiles, tileEwa, *shearWarp, skipped}, scene, cam, rs, size,
                          repeats, row);
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
          imagesDir + "/" + fileName(in.name) + "_" + std::to_string(size) + "_";
      if (!imagesDir.empty()) {
        writePng(stem + "ewa.png", ewa.readImage());
        if (row.shearWarpMs >= 0) writePng(stem + "shearwarp.png", shearWarp->readImage());
        if (row.tileEwaMs >= 0)
          writePng(stem + "tile-ewa.png",
                   tileEwaImage(tileEwa.picture(), size, size, rs.background));
      }
      for (const char* mapper : {"cpu", "gpu"}) {
        if (!vtkWorks) break;
        std::vector<std::string> args = vtkCameraArguments(cam, scene.volume);
        args.insert(args.end(), {"--size", std::to_string(size), "--repeats",
                                 std::to_string(repeats), "--mapper", mapper});
        if (!imagesDir.empty())
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
              json  ? ReportFormat::Json
              : csv ? ReportFormat::Csv
                    : ReportFormat::Table);
  return failed ? 1 : 0;
}

}  // namespace
}  // namespace ewa

int main(int argc, char** argv) {
  return ewa::benchmarkMain("ewaview-compare", ewa::run, argc, argv);
}
