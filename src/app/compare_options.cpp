// ewaview-compare's command line: its options, the EWA settings they make, the settings line.
#include "app/compare_options.h"

#include <cmath>
#include <cstdio>

#include "app/bench_support.h"
#include "app/vtk_runner.h"
#include "core/kernel_lattice.h"
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
  app.add_option("--kernel-width", o.settings.kernelWidth,
                 "EWA kernel sigma in voxel spacings, 0.3 to 2 (default 0.7)")
      ->check(CLI::Range(kMinKernelWidth, kMaxKernelWidth));
  app.add_option("--cutoff", o.settings.cutoff, "EWA footprint cutoff r = dx^T Q dx (default 5)")
      ->check(CLI::Range(0.25, 64.0));
  app.add_option("--depth-cutoff", o.settings.depthCutoff,
                 "EWA kernels' depth extent in squared sigmas, or inf (default 1)")
      ->check(CLI::Range(0.25, double(INFINITY)));
  app.add_option("--classification", o.text.classification,
                 "EWA: transfer function per pixel (post, default) or per voxel (pre)")
      ->check(CLI::IsMember({"pre", "post"}));
  app.add_option("--slab-preintegration", o.text.slabPreintegration,
                 "EWA post-classification: slab value pairs through the pre-integration table "
                 "(on, default) or each slab's value alone (off)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--slab-samples", o.settings.slabSamples,
                 "EWA post-classification, pre-integrated: depth samples a slab, 4 (default) or 2")
      ->check(CLI::IsMember({2, 4}));
  app.add_option("--slab-thickness", o.settings.slabThickness,
                 "EWA: slab thickness in voxels of the smallest spacing (default 2)")
      ->check(CLI::Range(0.25, 1000.0));
  app.add_option("--slab-passes", o.text.slabPasses,
                 "EWA, 4 samples a slab: splat each slab once into both images (1) or once into "
                 "each (2); auto (default): 1 on software rasterizers, else the faster as timed")
      ->check(CLI::IsMember({"auto", "1", "2"}));
  app.add_option("--prefilter", o.settings.classification.prefilter,
                 "EWA post-classification: value prefilter strength (default 0.04)")
      ->check(CLI::Range(0.0, kMaxPrefilter));
  app.add_option("--occlusion-culling", o.text.occlusionCulling,
                 "EWA: occlusion culling auto (default: off on software rasterizers), on or off")
      ->check(CLI::IsMember({"auto", "on", "off"}));
  app.add_option("--slab-rects", o.slabRects,
                 "EWA: each slab's passes cut to the pixels its kernels reach (on, default) or "
                 "over the whole image (off)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--slab-resolution", o.text.slabResolution,
                 "EWA: slabs splatted into images as coarse as their kernels allow (auto, "
                 "default) or at full resolution (full)")
      ->check(CLI::IsMember({"auto", "full"}));
  app.add_option("--slab-precision", o.text.slabPrecision,
                 "EWA: slab images of half floats (half) or floats (float); auto (default): "
                 "half for kernel widths up to 1 unless shaded and post-classified. The bare "
                 "sprites draw into the same")
      ->check(CLI::IsMember({"auto", "half", "float"}));
  app.add_option("--partition", o.partition,
                 "EWA: where the slab partition is built: auto (default: the CPU on software "
                 "rasterizers, the GPU elsewhere), gpu or cpu")
      ->check(CLI::IsMember({"auto", "gpu", "cpu"}));
  app.add_flag("--shading", o.settings.lighting.enabled, "EWA: Phong shading with a head light");
  app.add_option("--post-normals", o.text.postNormals,
                 "EWA post-classified, with --shading: field, voxel or ray (default) normals")
      ->check(CLI::IsMember({"field", "voxel", "ray"}));
  app.add_option("--tile-size", o.tileSize,
                 "Pixels a side of the compute tiles of the tiles_ms and tile_ewa_ms columns (8 or "
                 "16, default 16)")
      ->check(CLI::IsMember({8, 16}));
  app.add_option("--shader-dir", o.shaderDir, "Load shaders from this folder (development)");
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
