// The command-line options of compositing, shading, surface splats and the X-ray map.
#pragma once

#include <optional>
#include <string>

#include "render/renderer.h"

namespace CLI {
class App;
}

namespace ewa {

// Text-valued options as CLI11 reads them, turned into settings after parsing; each starts as
// the name of the settings' default.
struct RenderOptionText {
  explicit RenderOptionText(const RenderSettings& defaults = RenderSettings{});
  std::string compositing;
  std::string xrayMap;
  std::string gradient;
  std::string classification;  // empty: post, or pre with surface splats
  std::string slabPreintegration;
  std::string postNormals;
  std::string splatter;
  std::string occlusionCulling;
  std::string slabResolution;
  std::string slabPrecision;
  std::string slabPasses;
  std::optional<double> surfaceValue;
  std::optional<double> surfaceOpacity;
};

// Adds --classification, --slab-preintegration, --slab-samples, --prefilter, --post-normals,
// --splatter, --compositing, --termination, --occlusion-culling, --slab-resolution,
// --slab-precision, --xray-map, --xray-scale, --shading, --ambient, --diffuse, --specular,
// --shininess, --gradient, --surface-threshold, --surface-opacity-threshold,
// --surface-min-gradient and --surface-opacity to `app`, writing into `settings` and `text`; both
// must outlive the parse.
void addShadingOptions(CLI::App& app, RenderSettings& settings, RenderOptionText& text);
// Applies the parsed text options; returns a usage error message, or "" when all is well.
std::string finishShadingOptions(const RenderOptionText& text, RenderSettings* settings);

}  // namespace ewa
