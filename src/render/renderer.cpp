// Names of the render modes, and the footprint parameters the render settings imply.
#include "render/renderer.h"

#include <algorithm>

namespace ewa {

const char* renderModeName(RenderMode mode) {
  switch (mode) {
    case RenderMode::Composite: return "composite";
    case RenderMode::XRay: return "xray";
  }
  return "?";
}

FootprintParams footprintParams(const RenderSettings& settings, const glm::dvec3& spacing) {
  FootprintParams params;
  params.filter = settings.filter;
  params.cutoff = settings.cutoff;
  params.minSpacing = std::min({spacing.x, spacing.y, spacing.z});
  params.nearDepth = params.minSpacing;
  return params;
}

bool parseRenderMode(const std::string& text, RenderMode* mode) {
  if (text == "composite") *mode = RenderMode::Composite;
  else if (text == "xray") *mode = RenderMode::XRay;
  else return false;
  return true;
}

const char* rendererKindName(RendererKind kind) {
  return kind == RendererKind::ShearWarp ? "shearwarp" : "splat";
}

bool parseRendererKind(const std::string& text, RendererKind* kind) {
  if (text == "splat") *kind = RendererKind::Splat;
  else if (text == "shearwarp") *kind = RendererKind::ShearWarp;
  else return false;
  return true;
}

}  // namespace ewa
