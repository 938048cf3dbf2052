// Standard axis views, framed like Camera::frame does.
#include "core/camera_views.h"

#include <algorithm>

namespace ewa {

const char* axisViewName(AxisView view) {
  switch (view) {
    case AxisView::PlusX:
      return "+X";
    case AxisView::MinusX:
      return "-X";
    case AxisView::PlusY:
      return "+Y";
    case AxisView::MinusY:
      return "-Y";
    case AxisView::PlusZ:
      return "+Z";
    case AxisView::MinusZ:
      return "-Z";
  }
  return "?";
}

glm::dvec3 axisViewDirection(AxisView view) {
  switch (view) {
    case AxisView::PlusX:
      return {1, 0, 0};
    case AxisView::MinusX:
      return {-1, 0, 0};
    case AxisView::PlusY:
      return {0, 1, 0};
    case AxisView::MinusY:
      return {0, -1, 0};
    case AxisView::PlusZ:
      return {0, 0, 1};
    case AxisView::MinusZ:
      return {0, 0, -1};
  }
  return {0, 0, -1};
}

glm::dvec3 axisViewUp(AxisView view, bool patientFrame) {
  if (view == AxisView::PlusZ || view == AxisView::MinusZ)
    return patientFrame ? glm::dvec3(0, -1, 0) : glm::dvec3(0, 1, 0);
  return glm::dvec3(0, 0, 1);
}

const char* axisViewLabel(AxisView view, bool patientFrame) {
  if (!patientFrame) return axisViewName(view);
  switch (view) {
    case AxisView::PlusX:
      return "R";
    case AxisView::MinusX:
      return "L";
    case AxisView::PlusY:
      return "A";
    case AxisView::MinusY:
      return "P";
    case AxisView::PlusZ:
      return "I";
    case AxisView::MinusZ:
      return "S";
  }
  return "?";
}

const char* axisViewKeysHint(bool patientFrame) {
  return patientFrame ? "keys 1-6: from the patient's right, left, anterior, posterior, "
                        "inferior, superior (LPS patient axes)"
                      : "keys 1-6: +X -X +Y -Y +Z -Z";
}

Camera cameraForAxisView(const Camera& camera, AxisView view, const glm::dvec3& lo,
                         const glm::dvec3& hi, double aspect, bool patientFrame) {
  Camera out = camera;
  // frame() takes the direction from the focal point to the eye: the opposite of the look.
  out.frame(lo, hi, -axisViewDirection(view), axisViewUp(view, patientFrame), aspect);
  return out;
}

Camera initialVolumeView(const Camera& camera, const glm::dvec3& lo, const glm::dvec3& hi,
                         double aspect, bool patientFrame) {
  // A slab (a few slices, a single image) seen edge on shows a line: look through its face.
  const glm::dvec3 extent = hi - lo;
  int thin = 0;
  for (int k = 1; k < 3; ++k)
    if (extent[k] < extent[thin]) thin = k;
  const double largest = std::max(extent.x, std::max(extent.y, extent.z));
  const bool slab = extent[thin] < kSlabRatio * largest;
  if (patientFrame) {
    // The anterior view, else axial slices from the feet and sagittal ones from the right.
    const AxisView view = !slab || thin == 1 ? AxisView::PlusY
                          : thin == 2        ? AxisView::PlusZ
                                             : AxisView::PlusX;
    return cameraForAxisView(camera, view, lo, hi, aspect, true);
  }
  if (slab && thin != 2)
    return cameraForAxisView(camera, thin == 0 ? AxisView::MinusX : AxisView::MinusY, lo, hi,
                             aspect);
  Camera out = camera;
  out.frame(lo, hi, glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0), aspect);
  return out;
}

Camera turntableCamera(const Camera& start, int index, int count) {
  Camera camera = start;
  // One orbit per frame from the start (not accumulated), so rounding does not drift.
  if (count > 0) camera.orbit(360.0 * double(index) / double(count), 0.0);
  return camera;
}

}  // namespace ewa
