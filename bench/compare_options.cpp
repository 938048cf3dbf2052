// ewaview-compare's command line: its options, the EWA settings they make, the settings line.
#include "bench/compare_options.h"

#include <cmath>
#include <cstdio>

#include "app/option_binding.h"
#include "bench/bench_support.h"
#include "bench/vtk_runner.h"
#include "core/post_classification.h"
#include "core/value_prefilter.h"

namespace ewa {

CompareOptions::CompareOptions() : data(sharedDataDir()), script(VtkRunner::defaultScript()) {
  text.classification = classificationModeName(settings.classification.mode);
  // The EWA column is the rasterized frame; the tile_ewa column times the tiles beside it.
  text.splatter = splatterName(Splatter::Raster);
}

void addCompareOptions(CLI::App& app, CompareOptions& o) {
  app.add_option("--data", o.data,
                 "Folder with engine/, bonsai/ and cthead/ (default ../shared/data)");
  app.add_option("--volumes", o.volumes,
                 "Subset of engine, bonsai, cthead (default: all three, none with --synthetic)")
      ->delimiter(',')
      ->check(CLI::IsMember({"engine", "bonsai", "cthead"}));
  app.add_option("--synthetic", o.synthetic,
                 "Also a synthetic volume NAME:N as ewaview --synthetic makes it (repeatable)");
  app.add_option("--sizes", o.sizes, "Image sizes (width = height; default 512,1024)")
      ->delimiter(',')
      ->check(CLI::Range(16, 4096));
  app.add_option("--repeats", o.repeats, "Timed frames per method after a warm-up (default 5)")
      ->check(CLI::Range(1, 1000));
  app.add_flag("--csv", o.csv, "Print CSV instead of the table");
  app.add_flag("--json", o.json, "Print one JSON document instead of the table")->excludes("--csv");
  app.add_option("--images", o.imagesDir,
                 "Save each method's picture as DIR/VOLUME_SIZE_METHOD.png, to compare by eye");
  app.add_flag("--no-vtk", o.noVtk, "Do not time VTK's ray casters");
  app.add_option("--skip", o.skip,
                 "Methods not to time, their columns left '-': sprites, tiles (tiles_ms), "
                 "tile-ewa (tile_ewa_ms), cpu (cpu_ms), shearwarp")
      ->delimiter(',')
      ->check(CLI::IsMember({"sprites", "tiles", "tile-ewa", "cpu", "shearwarp"}));
  app.add_option("--vtk-script", o.script, "Path of vtk_raycast_bench.py");
  app.add_flag("--orthographic", o.orthographic, "Parallel projection (default: perspective)");
  // The EWA column's settings: ewaview's own options, as its --help describes them.
  addTableOption(app, "--kernel-width", o.settings.kernelWidth);
  addTableOption(app, "--cutoff", o.settings.cutoff);
  addTableOption(app, "--depth-cutoff", o.settings.depthCutoff);
  addTableOption(app, "--classification", o.text.classification);
  addTableOption(app, "--slab-preintegration", o.text.slabPreintegration);
  addTableOption(app, "--slab-samples", o.settings.slabSamples);
  addTableOption(app, "--slab-thickness", o.settings.slabThickness);
  addTableOption(app, "--slab-passes", o.text.slabPasses);
  addTableOption(app, "--prefilter", o.settings.classification.prefilter);
  addTableOption(app, "--occlusion-culling", o.text.occlusionCulling);
  app.add_option("--slab-rects", o.slabRects,
                 "EWA: each slab's passes cut to the pixels its kernels reach (on, default) or "
                 "over the whole image (off)")
      ->check(CLI::IsMember({"on", "off"}));
  addTableOption(app, "--slab-resolution", o.text.slabResolution);
  addTableOption(app, "--slab-precision", o.text.slabPrecision);  // the bare sprites' too
  app.add_option("--partition", o.partition,
                 "EWA: where the slab partition is built: auto (default: the CPU on software "
                 "rasterizers, the GPU elsewhere), gpu or cpu")
      ->check(CLI::IsMember({"auto", "gpu", "cpu"}));
  addTableFlag(app, "--shading", o.settings.lighting.enabled);
  addTableOption(app, "--post-normals", o.text.postNormals);
  app.add_option("--tile-size", o.tileSize,
                 "Pixels a side of the compute tiles of the tiles_ms and tile_ewa_ms columns (8 or "
                 "16, default 16)")
      ->check(CLI::IsMember({8, 16}));
  addTableOption(app, "--shader-dir", o.shaderDir);
  addBackendOption(app, o.backend);
}

void applyCompareOptions(CompareOptions& o) {
  if (o.volumes.empty() && o.synthetic.empty()) o.volumes = {"engine", "bonsai", "cthead"};
  // No surface options here, the only ones finishShadingOptions can refuse.
  finishShadingOptions(o.text, &o.settings);
}

std::string ewaSettingsText(const CompareOptions& o, bool occlusionCulling, bool gpuPartition) {
  const std::string shadingText =
      !o.settings.lighting.enabled ? ""
      : o.text.classification == "pre"
          ? ", shaded"
          : std::string(", shaded with ") + postNormalsName(o.settings.postNormals) + " normals";
  char ewaText[480], prefilterText[64];
  std::snprintf(prefilterText, sizeof prefilterText, ", prefilter %g%s",
                o.settings.classification.prefilter,
                o.text.slabPreintegration == "on"
                    ? (o.settings.slabSamples < 4   ? ", 2 samples a slab"
                       : o.settings.slabPasses == 0 ? ", 4 samples a slab"
                       : o.settings.slabPasses == 1 ? ", 4 samples a slab in 1 pass"
                                                    : ", 4 samples a slab in 2 passes")
                    : "");
  std::snprintf(ewaText, sizeof ewaText,
                "kernel width %.2f, cutoff %g, depth cutoff %g, slabs %g thick, "
                "%s-classification%s%s, %s slab images, occlusion culling %s%s%s%s, "
                "slab partition on the %s%s%s",
                o.settings.kernelWidth, o.settings.cutoff, o.settings.depthCutoff,
                o.settings.slabThickness, o.text.classification.c_str(),
                o.text.classification == "post" && o.text.slabPreintegration == "off"
                    ? " without slab pre-integration"
                    : "",
                o.text.classification == "post" ? prefilterText : "",
                halfFloatSlabs(o.settings) ? "half-float" : "float",
                occlusionCulling ? "on" : "off", o.text.occlusionCulling == "auto" ? " (auto)" : "",
                o.slabRects == "on" ? "" : ", whole-image slab passes",
                o.text.slabResolution == "auto" ? "" : ", full-resolution slabs",
                gpuPartition ? "GPU" : "CPU", o.partition == "auto" ? " (auto)" : "",
                shadingText.c_str());
  return ewaText;
}

}  // namespace ewa
