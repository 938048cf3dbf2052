// The command-line options of compositing, shading, surface splats and the X-ray map.
#pragma once

#include <optional>
#include <string>

#include "render/renderer.h"

namespace CLI {
class App;
}

namespace ewa {

// Text-valued options as CLI11 reads them, turned into settings after parsing.
struct RenderOptionText {
  std::string compositing = "front-to-back";
  std::string xrayMap = "exp";
  std::string gradient = "central";
  std::string classification;  // empty: post, or pre with surface splats
  std::string slabPreintegration = "on";
  std::string postNormals = "ray";
  std::string splatter = "auto";
  std::string occlusionCulling = "auto";
  std::string slabResolution = "auto";
  std::string slabPrecision = "auto";
  std::string slabPasses = "auto";
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
