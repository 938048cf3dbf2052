// The crop box drawn over the picture, with a handle on each face that drags that face along
// its axis (ImGui: the handles are tiny windows, so a press on one never reaches the camera).
#pragma once

#include "core/camera.h"
#include "core/clip_region.h"

namespace ewa {

struct CropHandleEdits {
  bool changed = false;   // a face moved this frame
  bool dragging = false;  // a handle is held
};

// Draws the box's edges and face handles for `camera` (the picture fills ImGui's display) and
// applies drags; nothing when the crop box is off. The box stays at least `minThickness` thick.
CropHandleEdits drawCropBoxHandles(ClipRegion& region, const Camera& camera, double minThickness);

}  // namespace ewa
