// The panel's collapsed "Advanced rendering" section: the renderer's own knobs.
#pragma once

#include "render/renderer.h"
#include "ui/layout_log.h"

namespace ewa {

// Draws the section's header and, when it is open, its controls (renderer, filter, cutoffs,
// kernel width, classification, slabs, compositing, shading terms, surface splats) inside the
// current ImGui window, editing `settings` and the "coarser while moving" switch
// `levelOfDetail`. Returns true when a setting changed (`*levelOfDetailChanged` says whether the
// switch did). [valueMin, valueMax] is the volume's value range. `layout` records the header
// ("section-advanced") and the knobs ("knob-cutoff", ...) for the window tests.
bool drawAdvancedRendering(RenderSettings& settings, double valueMin, double valueMax,
                           bool& levelOfDetail, bool* levelOfDetailChanged, LayoutLog& layout);

}  // namespace ewa
