// renderLayers: one volume's picture, or the channels' pictures overlaid.
#include "app/scene_render.h"

#include <stdexcept>

#include "core/channel_overlay.h"

namespace ewa {

std::vector<RenderLayer> sceneLayers(const Scene& scene) {
  std::vector<RenderLayer> layers{{&scene.volume, &scene.transferFunction}};
  for (const SceneChannel& c : scene.moreChannels)
    layers.push_back({&c.volume, &c.transferFunction});
  return layers;
}

Image8 renderLayers(HeadlessSession& session, const std::vector<RenderLayer>& layers,
                    const Camera& camera, const RenderSettings& settings, int width, int height) {
  if (layers.empty()) throw std::invalid_argument("renderLayers: no volume to draw");
  const Volume& first = *layers.front().volume;
  if (layers.size() == 1)
    return session.render(first, *layers.front().transferFunction, camera, settings, width, height);
  RenderSettings alone = settings;
  std::vector<Image8> overBlack, overWhite;
  const bool black = settings.background == glm::dvec3(0.0);
  for (size_t i = 0; i < layers.size(); ++i) {
    alone.background = glm::dvec3(0.0);
    overBlack.push_back(session.renderBare(*layers[i].volume, *layers[i].transferFunction, camera,
                                           alone, width, height, i));
    if (black) continue;
    alone.background = glm::dvec3(1.0);
    overWhite.push_back(session.renderBare(*layers[i].volume, *layers[i].transferFunction, camera,
                                           alone, width, height, i));
  }
  Image8 image = overlayChannels(overBlack, overWhite, settings.background);
  session.drawAxes(image, camera, first);
  return image;
}

}  // namespace ewa
