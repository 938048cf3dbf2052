// A scene's picture from a HeadlessSession: its volume, or with --channel all its channels
// overlaid.
#pragma once

#include <vector>

#include "app/headless_session.h"
#include "app/scene.h"

namespace ewa {

// One volume to draw and its transfer function; both must outlive the session's use of them.
struct RenderLayer {
  const Volume* volume = nullptr;
  const TransferFunction* transferFunction = nullptr;
};

// The scene's volume and, with --channel all, its other channels, in order.
std::vector<RenderLayer> sceneLayers(const Scene& scene);

// One layer: the session's picture of it. Several: each drawn alone by a slot of its own over
// black (and, for a background that is not black, over white too, for its opacity) and the
// pictures overlaid (overlayChannels: the colours added); the axes drawn once, on top.
Image8 renderLayers(HeadlessSession& session, const std::vector<RenderLayer>& layers,
                    const Camera& camera, const RenderSettings& settings, int width, int height);

}  // namespace ewa
