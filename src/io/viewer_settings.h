// ViewerSettings: what the window remembers between runs, in a per-user JSON file.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/clip_region.h"
#include "core/ewa_footprint.h"
#include "core/value_prefilter.h"

namespace ewa {

struct ViewerSettings {
  static constexpr size_t kMaxRecentFiles = 10;

  int windowWidth = 1024;
  int windowHeight = 768;
  std::vector<std::string> recentFiles;  // most recent first
  std::string lastTransferFunction;      // path of the last transfer function loaded or saved
  std::string screenshotDir;             // empty: the current folder
  int captureScale = 1;                  // screenshots and turntables at 1 to 4 times the window
  // Render settings (kept here as plain values: this file is read before any GL exists).
  FilterMode filter = FilterMode::Ewa;
  std::string renderMode = "composite";
  double cutoff = 5.0;                   // RenderSettings' default
  double depthCutoff = 1.0;              // RenderSettings' default; infinite: uncut ("inf")
  double kernelWidth = 0.7;              // RenderSettings' default
  std::string classification = "post";   // "pre" or "post"
  bool slabPreintegration = true;        // RenderSettings' default
  int slabSamples = 4;                   // RenderSettings' default: 2 or 4
  double prefilter = kDefaultPrefilter;  // post-classification's value prefilter
  std::string postNormals = "ray";       // "ray", "field" or "voxel"
  double slabThickness = 2.0;            // RenderSettings' default
  bool coarseSlabs = true;               // RenderSettings' default (--slab-resolution auto)
  glm::dvec3 background{0.0};
  bool levelOfDetail = true;  // coarser level while moving
  bool axes = true;           // the orientation axes in the corner (X key)
  // The crop box and planes of the last session and the volume they were for (its absolute
  // path, or "synthetic:NAME"): restored only when that volume opens again.
  ClipRegion clip;
  std::string clipVolume;
};

// The folder for ewaview's settings: $EWAVIEW_CONFIG_DIR if set (tests point it at a scratch
// folder), else $XDG_CONFIG_HOME/ewaview, else $HOME/.config/ewaview; empty when none is known.
std::string defaultConfigDir();
std::string settingsPathIn(const std::string& configDir);  // configDir/settings.json
std::string imguiIniPathIn(const std::string& configDir);  // configDir/imgui.ini

// Moves `path` to the front of the list (no duplicates), keeping at most kMaxRecentFiles.
void addRecentFile(std::vector<std::string>& recent, const std::string& path);

std::string viewerSettingsToJson(const ViewerSettings& settings);
// Unknown keys are ignored and missing ones keep their defaults, so old files keep working;
// values out of range are clamped to sane ones. Throws std::runtime_error("name: problem")
// for text that is not a JSON object or has values of the wrong type.
ViewerSettings viewerSettingsFromJson(const std::string& text, const std::string& name);
// A missing file gives the defaults; throws std::runtime_error("path: problem") for a bad one.
ViewerSettings loadViewerSettings(const std::string& path);
// Atomic (temporary file and rename); creates the folder. Throws std::runtime_error.
void saveViewerSettings(const std::string& path, const ViewerSettings& settings);

}  // namespace ewa
