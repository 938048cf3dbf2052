// The panel's "Crop and clip" section: the crop box's numbers and on/off, and clipping planes
// placed from the current view (through the focal point, facing the camera), each moved along
// its normal with a slider and switched on or off.
#pragma once

#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/clip_region.h"

namespace ewa {

struct ClipPanelEdits {
  bool changed = false;   // the region changed this frame: render again
  bool dragging = false;  // a slider or number is being dragged (the viewer stays coarse)
};

// Draws the section's controls inside the current ImGui window (under the header the control
// panel draws), editing `region`. [boundsMin, boundsMax] is the volume's world box (the
// crop box starts as it, sliders span it); new planes go through `camera`'s focal point with
// their normal towards the camera (the half facing the viewer is cut away).
ClipPanelEdits drawClipControls(ClipRegion& region, const glm::dvec3& boundsMin,
                                const glm::dvec3& boundsMax, const Camera& camera);

// The plane through camera's focal point facing the camera, keeping the far half.
ClipPlane planeFacingCamera(const Camera& camera);
// Signed distance of the plane from `centre` along its unit normal, and the plane moved so
// that this distance becomes `offset` (the slider's value).
double planeOffset(const ClipPlane& plane, const glm::dvec3& centre);
void setPlaneOffset(ClipPlane& plane, const glm::dvec3& centre, double offset);

}  // namespace ewa
