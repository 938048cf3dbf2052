// ewaview-compare's command line: its options, the EWA settings they make and the line that
// states those settings in the report.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app/render_options.h"
#include "render/renderer.h"

namespace ewa {

struct CompareOptions {
  CompareOptions();
  std::string data, imagesDir, backend = "osmesa", shaderDir, script;
  std::vector<std::string> volumes, synthetic, skip;
  std::vector<int> sizes = {512, 1024};
  int repeats = 5;
  bool csv = false, json = false, noVtk = false, orthographic = false;
  RenderSettings settings;  // EWA's: the defaults unless --kernel-width, --cutoff, ...
  // As typed; applyCompareOptions turns them into `settings` as ewaview's own options are
  // (finishShadingOptions).
  RenderOptionText text;
  std::string slabRects = "on", partition = "auto";
  int tileSize = 16;
};

// Adds every option to `app`, bound to `o`.
void addCompareOptions(CLI::App& app, CompareOptions& o);
// After parsing: the default volumes and the typed choices into `o.settings`.
void applyCompareOptions(CompareOptions& o);
// "kernel width 0.70, cutoff 5, ...": the EWA column's settings, as the report states them.
std::string ewaSettingsText(const CompareOptions& o, bool occlusionCulling, bool gpuPartition);

}  // namespace ewa
