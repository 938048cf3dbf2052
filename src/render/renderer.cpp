// Names of the render modes, and the footprint parameters the render settings imply.
#include "render/renderer.h"

#include <algorithm>

namespace ewa {

const char* occlusionCullingName(OcclusionCulling mode) {
  switch (mode) {
    case OcclusionCulling::Auto:
      return "auto";
    case OcclusionCulling::On:
      return "on";
    case OcclusionCulling::Off:
      return "off";
  }
  return "?";
}

bool parseOcclusionCulling(const std::string& text, OcclusionCulling* mode) {
  for (OcclusionCulling m : {OcclusionCulling::Auto, OcclusionCulling::On, OcclusionCulling::Off})
    if (text == occlusionCullingName(m)) {
      *mode = m;
      return true;
    }
  return false;
}

const char* slabPrecisionName(SlabPrecision precision) {
  switch (precision) {
    case SlabPrecision::Auto:
      return "auto";
    case SlabPrecision::Half:
      return "half";
    case SlabPrecision::Float:
      return "float";
  }
  return "?";
}

bool parseSlabPrecision(const std::string& text, SlabPrecision* precision) {
  for (SlabPrecision p : {SlabPrecision::Auto, SlabPrecision::Half, SlabPrecision::Float})
    if (text == slabPrecisionName(p)) {
      *precision = p;
      return true;
    }
  return false;
}

bool halfFloatSlabs(const RenderSettings& settings) {
  if (settings.mode != RenderMode::Composite) return false;
  if (settings.slabPrecision == SlabPrecision::Auto)
    return settings.kernelWidth <= 1.0 && !(postClassified(settings) && settings.lighting.enabled);
  return settings.slabPrecision == SlabPrecision::Half;
}

const char* postNormalsName(PostNormals normals) {
  return normals == PostNormals::Field ? "field" : "voxel";
}

bool parsePostNormals(const std::string& text, PostNormals* normals) {
  for (PostNormals n : {PostNormals::Field, PostNormals::Voxel})
    if (text == postNormalsName(n)) {
      *normals = n;
      return true;
    }
  return false;
}

const char* renderModeName(RenderMode mode) {
  switch (mode) {
    case RenderMode::Composite:
      return "composite";
    case RenderMode::XRay:
      return "xray";
    case RenderMode::Mip:
      return "mip";
  }
  return "?";
}

void applyCloseUpSettings(RenderSettings* settings) {
  settings->classification.mode = ClassificationMode::Post;
  settings->classification.surface = SurfaceCriterion::None;
  const RenderSettings defaults;
  settings->slabPreintegration = true;
  settings->slabSamples = defaults.slabSamples;
  settings->classification.prefilter = defaults.classification.prefilter;
  settings->kernelWidth = defaults.kernelWidth;
  settings->cutoff = defaults.cutoff;
}

FootprintParams footprintParams(const RenderSettings& settings, const glm::dvec3& spacing) {
  FootprintParams params;
  params.filter = settings.filter;
  params.cutoff = settings.cutoff;
  params.minSpacing = std::min({spacing.x, spacing.y, spacing.z});
  params.cullDepth = params.minSpacing;
  params.swanSpacing = settings.kernelWidth * params.minSpacing;
  params.lowPass = lowPassVariance(settings);
  return params;
}

bool postClassified(const RenderSettings& settings) {
  return settings.classification.mode == ClassificationMode::Post &&
         settings.mode == RenderMode::Composite;
}

double lowPassVariance(const RenderSettings& settings) {
  if (settings.lowPass > 0.0) return std::min(settings.lowPass, 1.0);
  return postClassified(settings) ? kPostClassifiedLowPass : 1.0;
}

DepthProfile depthProfile(const RenderSettings& settings) {
  if (std::isinf(settings.depthCutoff)) return DepthProfile{};
  return depthProfile(std::min(settings.cutoff, settings.depthCutoff));
}

Classification splatClassification(const RenderSettings& settings) {
  Classification c = settings.classification;
  c.postMargin = postClassificationMargin(settings.cutoff, settings.kernelWidth);
  // X-ray and MIP classify each splat (pre) whatever the classification: their values stay the
  // data's.
  if (settings.mode != RenderMode::Composite) c.prefilter = 0.0;
  return c;
}

bool parseRenderMode(const std::string& text, RenderMode* mode) {
  if (text == "composite")
    *mode = RenderMode::Composite;
  else if (text == "xray")
    *mode = RenderMode::XRay;
  else if (text == "mip")
    *mode = RenderMode::Mip;
  else
    return false;
  return true;
}

const char* compositeOrderName(CompositeOrder order) {
  return order == CompositeOrder::BackToFront ? "back-to-front" : "front-to-back";
}

bool parseCompositeOrder(const std::string& text, CompositeOrder* order) {
  if (text == "front-to-back")
    *order = CompositeOrder::FrontToBack;
  else if (text == "back-to-front")
    *order = CompositeOrder::BackToFront;
  else
    return false;
  return true;
}

const char* xrayMapName(XRayMap map) {
  return map == XRayMap::Sum ? "sum" : "exp";
}

bool parseXRayMap(const std::string& text, XRayMap* map) {
  if (text == "exp")
    *map = XRayMap::Attenuation;
  else if (text == "sum")
    *map = XRayMap::Sum;
  else
    return false;
  return true;
}

const char* rendererKindName(RendererKind kind) {
  return kind == RendererKind::ShearWarp ? "shearwarp" : "splat";
}

void Renderer::beginFrame(const Camera& camera, const RenderSettings& settings, int width,
                          int height) {
  pending_ = PendingFrame{camera, settings, width, height};
}

bool Renderer::stepFrame(double /*budgetMs*/) {
  if (!pending_) return true;
  const PendingFrame frame = std::move(*pending_);
  pending_.reset();
  render(frame.camera, frame.settings, frame.width, frame.height);
  return true;
}

double Renderer::frameProgress() const {
  return pending_ ? 0.0 : 1.0;
}

bool parseRendererKind(const std::string& text, RendererKind* kind) {
  if (text == "splat")
    *kind = RendererKind::Splat;
  else if (text == "shearwarp")
    *kind = RendererKind::ShearWarp;
  else
    return false;
  return true;
}

}  // namespace ewa
