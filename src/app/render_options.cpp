// The command-line options of compositing, shading, surface splats and the X-ray map (CLI11).
#include "app/render_options.h"

#include <CLI/CLI.hpp>
#include <cmath>

#include "app/option_binding.h"

namespace ewa {

RenderOptionText::RenderOptionText(const RenderSettings& s)
    : compositing(compositeOrderName(s.order)),
      xrayMap(xrayMapName(s.xrayMap)),
      gradient(gradientModeName(s.classification.gradient)),
      slabPreintegration(s.slabPreintegration ? "on" : "off"),
      postNormals(postNormalsName(s.postNormals)),
      splatter(splatterName(s.splatter)),
      occlusionCulling(occlusionCullingName(s.occlusionCulling)),
      slabResolution(s.coarseSlabs ? "auto" : "full"),
      slabPrecision(slabPrecisionName(s.slabPrecision)),
      slabPasses(slabPassesName(s.slabPasses)) {}

void addShadingOptions(CLI::App& app, RenderSettings& s, RenderOptionText& p) {
  addTableOption(app, "--classification", p.classification);
  addTableOption(app, "--slab-preintegration", p.slabPreintegration);
  addTableOption(app, "--slab-samples", s.slabSamples);
  addTableOption(app, "--slab-passes", p.slabPasses);
  addTableOption(app, "--prefilter", s.classification.prefilter);
  addTableOption(app, "--post-normals", p.postNormals);
  addTableOption(app, "--splatter", p.splatter);
  addTableOption(app, "--compositing", p.compositing);
  addTableOption(app, "--termination", s.terminationOpacity);
  addTableOption(app, "--occlusion-culling", p.occlusionCulling);
  addTableOption(app, "--slab-resolution", p.slabResolution);
  addTableOption(app, "--slab-precision", p.slabPrecision);
  addTableOption(app, "--xray-map", p.xrayMap);
  addTableOption(app, "--xray-scale", s.xrayScale);
  addTableFlag(app, "--shading", s.lighting.enabled);
  addTableOption(app, "--ambient", s.lighting.ambient);
  addTableOption(app, "--diffuse", s.lighting.diffuse);
  addTableOption(app, "--specular", s.lighting.specular);
  addTableOption(app, "--shininess", s.lighting.shininess);
  addTableOption(app, "--gradient", p.gradient);
  auto* value = addTableOption(app, "--surface-threshold", p.surfaceValue);
  auto* alpha = addTableOption(app, "--surface-opacity-threshold", p.surfaceOpacity);
  value->excludes(alpha);
  addTableOption(app, "--surface-min-gradient", s.classification.minGradient)->needs(alpha);
  addTableOption(app, "--surface-opacity", s.surfaceOpacity);
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
