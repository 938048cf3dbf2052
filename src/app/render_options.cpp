// The command-line options of compositing, shading, surface splats and the X-ray map (CLI11).
#include "app/render_options.h"

#include <CLI/CLI.hpp>
#include <cmath>

namespace ewa {

void addShadingOptions(CLI::App& app, RenderSettings& s, RenderOptionText& p) {
  app.add_option("--classification", p.classification,
                 "Transfer function applied per pixel to the splatted value (post, default) or "
                 "per voxel before splatting (pre; the default with surface splats)")
      ->check(CLI::IsMember({"pre", "post"}));
  app.add_option("--slab-preintegration", p.slabPreintegration,
                 "Post-classification: classify each pixel's values in two neighbouring slabs as "
                 "a pair through the pre-integration table (on, default), or each slab's value "
                 "alone (off)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--slab-samples", s.slabSamples,
                 "Post-classified and pre-integrated: each slab's values at 4 depths (its "
                 "quarters, default) or 2 (its halves; cheaper, softer in depth)")
      ->check(CLI::IsMember({2, 4}));
  app.add_option("--slab-passes", p.slabPasses,
                 "With 4 samples a slab: splat each slab's kernels once into both of its images "
                 "(1) or once into each (2: the same picture, faster on some GPUs); auto "
                 "(default): 1 on software rasterizers, elsewhere whichever timed frames find "
                 "faster")
      ->check(CLI::IsMember({"auto", "1", "2"}));
  app.add_option("--prefilter", s.classification.prefilter,
                 "Post-classification: sharpen each splat's value by B times its discrete "
                 "Laplacian, so the kernels come nearer interpolating the voxels (default 0.04; 0: "
                 "the data's values)")
      ->check(CLI::Range(0.0, kMaxPrefilter));
  app.add_option("--post-normals", p.postNormals,
                 "Post-classified, with --shading: normals from the gradient of the reconstructed "
                 "field (field; pre-integrated only, else voxel), the splats' voxel normals "
                 "(voxel), or the data's gradient read along each pixel's ray (ray, default: as a "
                 "ray caster shades; 4 bytes of GPU memory a voxel while shading)")
      ->check(CLI::IsMember({"field", "voxel", "ray"}));
  app.add_option(
         "--splatter", p.splatter,
         "Whole composite frames (headless): rasterized slab by slab (raster), in "
         "compute tiles (tiles: no rasterizer, no blending; front to back, "
         "post-classified only with 4 samples a slab and, shaded, field or ray "
         "normals, else rasterized), on the CPU (cpu: front to back, pre-classified only, else "
         "rasterized), or auto (default: raster on software GL, else the faster as "
         "timed frames find it)")
      ->check(CLI::IsMember({"raster", "tiles", "cpu", "auto"}));
  app.add_option("--compositing", p.compositing,
                 "Slab order: front-to-back (default) or back-to-front")
      ->check(CLI::IsMember({"front-to-back", "back-to-front"}));
  app.add_option("--termination", s.terminationOpacity,
                 "Front to back: stop a pixel at this opacity (default 0.99; 1 never stops)")
      ->check(CLI::Range(0.5, 1.0));
  app.add_option("--occlusion-culling", p.occlusionCulling,
                 "Front to back with termination: skip splats over pixels already opaque (on), "
                 "draw them (off), or auto (default: on, but off on software rasterizers); the "
                 "picture is the same")
      ->check(CLI::IsMember({"auto", "on", "off"}));
  app.add_option("--slab-resolution", p.slabResolution,
                 "Composite: splat each slab into an image as coarse as its kernels allow (auto, "
                 "default: 1.25 to 4 pixels a texel in quarter steps, where every footprint "
                 "stays 2 texels wide, read back bilinearly; not with shaded "
                 "post-classification) or at the picture's resolution (full)")
      ->check(CLI::IsMember({"auto", "full"}));
  app.add_option("--slab-precision", p.slabPrecision,
                 "Composite: slab images of half floats (half: within a few levels of float, "
                 "about twice as fast on a GPU) or floats (float); auto (default): half for "
                 "kernel widths up to 1 unless shaded and post-classified")
      ->check(CLI::IsMember({"auto", "half", "float"}));
  app.add_option("--xray-map", p.xrayMap, "X-ray gray: exp (exp(-sum), default) or sum")
      ->check(CLI::IsMember({"exp", "sum"}));
  app.add_option("--xray-scale", s.xrayScale, "X-ray: optical depth multiplied by this (default 1)")
      ->check(CLI::Range(1e-6, 1e6));
  app.add_flag("--shading", s.lighting.enabled, "Phong shading with a head light");
  app.add_option("--ambient", s.lighting.ambient, "Ambient term (default 0.3)")
      ->check(CLI::Range(0.0, 4.0));
  app.add_option("--diffuse", s.lighting.diffuse, "Diffuse term (default 0.7)")
      ->check(CLI::Range(0.0, 4.0));
  app.add_option("--specular", s.lighting.specular, "Specular term (default 0.25)")
      ->check(CLI::Range(0.0, 4.0));
  app.add_option("--shininess", s.lighting.shininess, "Specular exponent (default 24)")
      ->check(CLI::Range(1.0, 1000.0));
  app.add_option("--gradient", p.gradient, "Gradients: central (default) or smooth (Sobel-like)")
      ->check(CLI::IsMember({"central", "smooth"}));
  auto* value = app.add_option("--surface-threshold", p.surfaceValue,
                               "Surface splats on the iso-surface of this data value");
  auto* alpha = app.add_option("--surface-opacity-threshold", p.surfaceOpacity,
                               "Surface splats where the transfer function's opacity crosses this")
                    ->check(CLI::Range(0.0, 1.0));
  value->excludes(alpha);
  app.add_option("--surface-min-gradient", s.classification.minGradient,
                 "With --surface-opacity-threshold: least gradient, as a fraction of the value "
                 "range per voxel (default 0)")
      ->check(CLI::Range(0.0, 1.0))
      ->needs(alpha);
  app.add_option("--surface-opacity", s.surfaceOpacity,
                 "Opacity of the surface-splat layer seen along its normal (default 0.95)")
      ->check(CLI::Range(0.0, 0.999999));
}

std::string finishShadingOptions(const RenderOptionText& p, RenderSettings* s) {
  parseCompositeOrder(p.compositing, &s->order);
  parseOcclusionCulling(p.occlusionCulling, &s->occlusionCulling);
  parseXRayMap(p.xrayMap, &s->xrayMap);
  parseGradientMode(p.gradient, &s->classification.gradient);
  parseClassificationMode(p.classification, &s->classification.mode);
  s->slabPreintegration = p.slabPreintegration == "on";
  s->coarseSlabs = p.slabResolution == "auto";
  parseSlabPrecision(p.slabPrecision, &s->slabPrecision);
  parseSlabPasses(p.slabPasses, &s->slabPasses);
  parsePostNormals(p.postNormals, &s->postNormals);
  parseSplatter(p.splatter, &s->splatter);
  if (p.surfaceValue) {
    if (!std::isfinite(*p.surfaceValue)) return "--surface-threshold: not a finite number";
    s->classification.surface = SurfaceCriterion::Value;
    s->classification.threshold = *p.surfaceValue;
  } else if (p.surfaceOpacity) {
    s->classification.surface = SurfaceCriterion::Opacity;
    s->classification.threshold = *p.surfaceOpacity;
  }
  // Surface splats need pre-classification: asking for them without a classification picks it.
  if (p.classification.empty() && s->classification.surface != SurfaceCriterion::None)
    s->classification.mode = ClassificationMode::Pre;
  if (s->classification.mode == ClassificationMode::Post &&
      s->classification.surface != SurfaceCriterion::None)
    return "post-classification (--classification post, --close-up) draws no surface splats: "
           "drop --surface-threshold and --surface-opacity-threshold";
  return "";
}

}  // namespace ewa
