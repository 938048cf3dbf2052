// windowConfig: saved settings where the command line says nothing.
#include "app/window_config.h"

#include <filesystem>
#include <iostream>

#include "io/viewer_settings.h"

namespace ewa {

Options windowConfig(const Options& options, const std::string& clipKey, ViewerConfig* config) {
  config->configDir = options.configDir.empty() ? defaultConfigDir() : options.configDir;
  if (!config->configDir.empty()) {
    try {
      config->saved = loadViewerSettings(settingsPathIn(config->configDir));
    } catch (const std::exception& e) {
      std::cerr << "ewaview: " << e.what() << " (using defaults)\n";
    }
  }
  Options o = options;
  if (!o.resolutionGiven) {
    o.width = config->saved.windowWidth;
    o.height = config->saved.windowHeight;
  }
  if (!o.renderOptionsGiven) {
    o.render.filter = config->saved.filter;
    parseRenderMode(config->saved.renderMode, &o.render.mode);
    o.render.cutoff = config->saved.cutoff;
    o.render.depthCutoff = config->saved.depthCutoff;
    o.render.kernelWidth = config->saved.kernelWidth;
    if (o.render.classification.surface == SurfaceCriterion::None)
      parseClassificationMode(config->saved.classification, &o.render.classification.mode);
    o.render.slabPreintegration = config->saved.slabPreintegration;
    o.render.slabSamples = config->saved.slabSamples;
    o.render.classification.prefilter = config->saved.prefilter;
    parsePostNormals(config->saved.postNormals, &o.render.postNormals);
    o.render.slabThickness = config->saved.slabThickness;
    o.render.coarseSlabs = config->saved.coarseSlabs;
    o.render.background = config->saved.background;
  }
  // The last session's crop box and planes, when it showed this volume and none are given.
  if (o.render.clip == ClipRegion{} && config->saved.clipVolume == clipKey)
    o.render.clip = config->saved.clip;
  if (o.axes) config->saved.axes = true;
  if (!o.tfFile.empty())
    config->saved.lastTransferFunction = std::filesystem::absolute(o.tfFile).string();
  config->width = o.width;
  config->height = o.height;
  config->settings = o.render;
  config->shaderDir = o.shaderDir;
  config->recordCameraPath = o.recordCameraPath;
  config->watch = o.watch;
  return o;
}

}  // namespace ewa
