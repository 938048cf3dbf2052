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
glm::dvec3 axisViewUp(AxisView view);

// `camera` (keeping its view angle and projection) turned to look along `view`, framing the
// box [lo, hi] in an image of the given aspect (width / height).
Camera cameraForAxisView(const Camera& camera, AxisView view, const glm::dvec3& lo,
                         const glm::dvec3& hi, double aspect);

// Frame `index` of a turntable of `count` frames: `start` orbited by index * 360 / count
// degrees about its view-up through the focal point (frame 0 is `start`).
Camera turntableCamera(const Camera& start, int index, int count);

}  // namespace ewa
