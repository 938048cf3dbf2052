// The panel's render-mode row and the advanced section's compositing, shading and surfaces.
#pragma once

#include "render/renderer.h"

namespace ewa {

// The render modes as radio buttons, and X-ray's map and scale while it is chosen; inside the
// current ImGui window. Returns true when something changed.
bool drawRenderMode(RenderSettings& settings);

// A "compositing, shading, surfaces" tree: order, termination, the shading terms (shading itself
// is switched in the view section), surface splats. [valueMin, valueMax] is the volume's value
// range (surface threshold). Returns true when something changed.
bool drawCompositingOptions(RenderSettings& settings, double valueMin, double valueMax);

}  // namespace ewa
