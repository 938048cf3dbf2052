// Headless rendering: a HeadlessSession's one frame, written as a PNG.
#include "app/headless.h"

#include <iostream>
#include <stdexcept>

#include "app/frame_stats.h"
#include "app/headless_session.h"
#include "app/scene_render.h"
#include "io/input_guard.h"
#include "io/png_io.h"

namespace ewa {

std::vector<std::string> sceneInputFiles(const Scene& scene, const Options& o) {
  std::vector<std::string> inputs = scene.volume.sourceFiles();
  for (const SceneChannel& channel : scene.moreChannels)
    for (const std::string& file : channel.volume.sourceFiles()) inputs.push_back(file);
  for (const std::string& file : {o.file, o.tfFile, o.bookmarks})
    if (!file.empty()) inputs.push_back(file);
  return inputs;
}

void refuseToOverwriteInputs(const std::string& output, const Scene& scene, const Options& o) {
  refuseToReplaceInputs(output, sceneInputFiles(scene, o));
}

void renderHeadless(const Scene& scene, const Options& o) {
  refuseToOverwriteInputs(o.output, scene, o);
  HeadlessSession session(o.backend, o.shaderDir);
  session.setAxes(o.axes);
  const std::vector<RenderLayer> layers = sceneLayers(scene);
  writePng(o.output, renderLayers(session, layers, initialCamera(scene.volume, o), o.render,
                                  o.width, o.height));
  if (const std::string note = session.takeNote(); !note.empty())
    std::cerr << "ewaview: " << note << std::endl;
  if (!o.stats) return;
  std::vector<RenderStats> channels;  // a channel's slot is its layer's place (renderLayers)
  for (size_t i = 0; i < layers.size(); ++i) channels.push_back(session.stats(i));
  std::cout << frameStatsJson(channels, rendererKindName(o.render.renderer), o.width, o.height)
            << std::endl;
}

}  // namespace ewa
