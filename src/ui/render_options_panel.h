// The panel section for compositing order, termination, shading, surface splats and X-ray.
#pragma once

#include "render/renderer.h"

namespace ewa {

// Draws the controls inside the current ImGui window, editing `settings`; returns true when
// something changed. [valueMin, valueMax] is the volume's value range (surface threshold).
bool drawRenderOptions(RenderSettings& settings, double valueMin, double valueMax);

}  // namespace ewa
