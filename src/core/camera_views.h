// Standard views: the camera looking along one of the six axes at the whole volume.
#pragma once

#include <string>

#include "core/camera.h"

namespace ewa {

// The six views of ParaView's toolbar, named by the direction the camera looks.
enum class AxisView { PlusX, MinusX, PlusY, MinusY, PlusZ, MinusZ };

constexpr AxisView kAxisViews[] = {AxisView::PlusX,  AxisView::MinusX, AxisView::PlusY,
                                   AxisView::MinusY, AxisView::PlusZ,  AxisView::MinusZ};

// "+X", "-X", ...
const char* axisViewName(AxisView view);
// Unit vector the camera looks along.
glm::dvec3 axisViewDirection(AxisView view);
// View-up used with it: +Z for views along X and Y, +Y for views along Z (ParaView's choice).
// In a patient frame (LPS) the views along Z have the anterior side (-Y) up instead, as
// radiologists show axial slices.
glm::dvec3 axisViewUp(AxisView view, bool patientFrame = false);

// The label of the view's button in a patient frame (LPS: +X left, +Y posterior, +Z superior):
// the side the eye is on ("R": looking along +X from the patient's right; then "L", "A" along
// +Y, "P", "I" along +Z, "S"); axisViewName's "+X" ... otherwise.
const char* axisViewLabel(AxisView view, bool patientFrame);
// What keys 1 to 6 do, for a tooltip.
const char* axisViewKeysHint(bool patientFrame);

// `camera` (keeping its view angle and projection) turned to look along `view`, framing the
// box [lo, hi] in an image of the given aspect (width / height).
Camera cameraForAxisView(const Camera& camera, AxisView view, const glm::dvec3& lo,
                         const glm::dvec3& hi, double aspect, bool patientFrame = false);

// A box thinner than this fraction of its longest side along one axis is a slab.
constexpr double kSlabRatio = 0.25;

// The first view of a volume with world bounds [lo, hi]: VTK's (from +Z, +Y up), or in a
// patient frame the anterior view (superior up), so a patient is seen face on. A slab (a few
// slices: kSlabRatio) is seen through its face instead of edge on: along its thin axis (from
// +X or +Y; in a patient frame axial slabs from the feet, anterior up, sagittal ones from the
// patient's right).
Camera initialVolumeView(const Camera& camera, const glm::dvec3& lo, const glm::dvec3& hi,
                         double aspect, bool patientFrame);

// Frame `index` of a turntable of `count` frames: `start` orbited by index * 360 / count
// degrees about its view-up through the focal point (frame 0 is `start`).
Camera turntableCamera(const Camera& start, int index, int count);

}  // namespace ewa
