// ViewerSettings: config folder lookup, JSON form, atomic saving.
#include "io/viewer_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/kernel_lattice.h"
#include "io/atomic_file.h"
#include "io/clip_region_json.h"
#include "io/side_file.h"

namespace ewa {

namespace {

using nlohmann::json;

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

}  // namespace

std::string defaultConfigDir() {
  if (std::string dir = env("EWAVIEW_CONFIG_DIR"); !dir.empty()) return dir;
  if (std::string xdg = env("XDG_CONFIG_HOME"); !xdg.empty()) return xdg + "/ewaview";
  if (std::string home = env("HOME"); !home.empty()) return home + "/.config/ewaview";
  return {};
}

std::string settingsPathIn(const std::string& dir) {
  return dir + "/settings.json";
}
std::string imguiIniPathIn(const std::string& dir) {
  return dir + "/imgui.ini";
}

void addRecentFile(std::vector<std::string>& recent, const std::string& path) {
  recent.erase(std::remove(recent.begin(), recent.end(), path), recent.end());
  recent.insert(recent.begin(), path);
  if (recent.size() > ViewerSettings::kMaxRecentFiles)
    recent.resize(ViewerSettings::kMaxRecentFiles);
}

std::string viewerSettingsToJson(const ViewerSettings& s) {
  json j;
  j["window_size"] = {s.windowWidth, s.windowHeight};
  j["recent_files"] = s.recentFiles;
  j["last_transfer_function"] = s.lastTransferFunction;
  j["screenshot_dir"] = s.screenshotDir;
  j["capture_scale"] = s.captureScale;
  j["render"] = {{"filter", filterModeName(s.filter)},
                 {"mode", s.renderMode},
                 {"cutoff", s.cutoff},
                 {"depth_cutoff", std::isfinite(s.depthCutoff) ? json(s.depthCutoff) : json("inf")},
                 {"kernel_width", s.kernelWidth},
                 {"classification", s.classification},
                 {"slab_preintegration", s.slabPreintegration},
                 {"slab_samples", s.slabSamples},
                 {"prefilter", s.prefilter},
                 {"post_normals", s.postNormals},
                 {"slab_thickness", s.slabThickness},
                 {"slab_resolution", s.coarseSlabs ? "auto" : "full"},
                 {"background", {s.background.r, s.background.g, s.background.b}},
                 {"level_of_detail", s.levelOfDetail},
                 {"axes", s.axes}};
  if (!s.clipVolume.empty()) {
    j["clip"] = clipRegionToJson(s.clip);
    j["clip"]["volume"] = s.clipVolume;
  }
  return j.dump(2) + "\n";
}

ViewerSettings viewerSettingsFromJson(const std::string& text, const std::string& name) {
  ViewerSettings s;
  try {
    const json j = json::parse(text);
    if (!j.is_object()) throw std::runtime_error("settings must be a JSON object");
    if (j.contains("window_size")) {
      const auto size = j.at("window_size").get<std::vector<int>>();
      if (size.size() == 2) {
        s.windowWidth = std::clamp(size[0], 64, 16384);
        s.windowHeight = std::clamp(size[1], 64, 16384);
      }
    }
    if (j.contains("recent_files")) {
      for (const std::string& f : j.at("recent_files").get<std::vector<std::string>>())
        if (!f.empty() && s.recentFiles.size() < ViewerSettings::kMaxRecentFiles)
          s.recentFiles.push_back(f);
    }
    s.lastTransferFunction = j.value("last_transfer_function", std::string());
    s.screenshotDir = j.value("screenshot_dir", std::string());
    s.captureScale = std::clamp(j.value("capture_scale", 1), 1, 4);
    if (j.contains("render")) {
      const json& r = j.at("render");
      FilterMode filter;
      if (parseFilterMode(r.value("filter", std::string("ewa")), &filter)) s.filter = filter;
      const std::string mode = r.value("mode", std::string("composite"));
      if (mode == "composite" || mode == "xray" || mode == "mip") s.renderMode = mode;
      const double cutoff = r.value("cutoff", s.cutoff);
      if (std::isfinite(cutoff)) s.cutoff = std::clamp(cutoff, 0.25, 64.0);
      if (r.contains("depth_cutoff")) {  // a number, or "inf" for the uncut profile
        const json& d = r.at("depth_cutoff");
        if (d.is_number() && std::isfinite(d.get<double>()))
          s.depthCutoff = std::clamp(d.get<double>(), 0.25, 64.0);
        else if (d == "inf")
          s.depthCutoff = INFINITY;
      }
      const double width = r.value("kernel_width", s.kernelWidth);
      if (std::isfinite(width)) s.kernelWidth = std::clamp(width, kMinKernelWidth, kMaxKernelWidth);
      const std::string classification = r.value("classification", s.classification);
      if (classification == "pre" || classification == "post") s.classification = classification;
      s.slabPreintegration = r.value("slab_preintegration", s.slabPreintegration);
      const int samples = r.value("slab_samples", s.slabSamples);
      if (samples == 2 || samples == 4) s.slabSamples = samples;
      const double prefilter = r.value("prefilter", s.prefilter);
      if (std::isfinite(prefilter)) s.prefilter = std::clamp(prefilter, 0.0, kMaxPrefilter);
      const std::string normals = r.value("post_normals", s.postNormals);
      if (normals == "field" || normals == "voxel") s.postNormals = normals;
      const double slab = r.value("slab_thickness", s.slabThickness);
      if (std::isfinite(slab)) s.slabThickness = std::clamp(slab, 0.05, 1000.0);
      const std::string resolution =
          r.value("slab_resolution", std::string(s.coarseSlabs ? "auto" : "full"));
      if (resolution == "auto" || resolution == "full") s.coarseSlabs = resolution == "auto";
      if (r.contains("background")) {
        const auto bg = r.at("background").get<std::vector<double>>();
        if (bg.size() == 3)
          for (int c = 0; c < 3; ++c)
            s.background[c] =
                std::isfinite(bg[size_t(c)]) ? std::clamp(bg[size_t(c)], 0.0, 1.0) : 0.0;
      }
      s.levelOfDetail = r.value("level_of_detail", true);
      s.axes = r.value("axes", true);
    }
    if (j.contains("clip")) {
      // A bad clip entry only loses the clip, not the other settings.
      try {
        s.clip = clipRegionFromJson(j.at("clip"));
        s.clipVolume = j.at("clip").value("volume", std::string());
      } catch (const std::exception&) {
        s.clip = ClipRegion{};
        s.clipVolume.clear();
      }
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(name + ": " + problemText(e));
  }
  return s;
}

ViewerSettings loadViewerSettings(const std::string& path) {
  if (!std::filesystem::exists(path)) return {};
  return viewerSettingsFromJson(readSideFile(path, "settings file"), path);
}

void saveViewerSettings(const std::string& path, const ViewerSettings& settings) {
  writeFileAtomically(path, viewerSettingsToJson(settings), /*makeParents=*/true);
}

}  // namespace ewa
