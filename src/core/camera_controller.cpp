// CameraController: turns mouse drags and scrolls into camera orbit, dolly and pan (no GL, no UI).
#include "core/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace ewa {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

CameraController::CameraController(const Camera& initial) : initial_(initial), camera_(initial) {}

void CameraController::setViewportSize(int width, int height) {
  width_ = std::max(width, 1);
  height_ = std::max(height, 1);
}

void CameraController::pressButton(MouseButton button, bool shift, double x, double y) {
  if (dragging()) return;
  switch (button) {
    case MouseButton::Left:
      mode_ = shift ? DragMode::Pan : DragMode::Orbit;
      break;
    case MouseButton::Middle:
      mode_ = DragMode::Pan;
      break;
    case MouseButton::Right:
      mode_ = DragMode::Dolly;
      break;
  }
  dragButton_ = button;
  lastX_ = x;
  lastY_ = y;
}

void CameraController::releaseButton(MouseButton button) {
  if (dragging() && button == dragButton_) mode_ = DragMode::None;
}

bool CameraController::moveCursor(double x, double y) {
  const double dx = x - lastX_;
  const double dy = y - lastY_;  // window coordinates: positive is down
  lastX_ = x;
  lastY_ = y;
  if (!dragging() || (dx == 0.0 && dy == 0.0)) return false;

  // Everything scales with the viewport height, so a drag feels the same at any window size.
  const double perPixel = 1.0 / height_;
  switch (mode_) {
    case DragMode::Orbit:
      // The grabbed surface follows the cursor: dragging right swings the eye left and dragging
      // up swings it down (Camera::orbit moves the eye right for positive azimuth and down for
      // positive elevation).
      camera_.orbit(-dx * perPixel * kOrbitDegreesPerViewport,
                    -dy * perPixel * kOrbitDegreesPerViewport);
      break;
    case DragMode::Dolly:
      camera_.dolly(std::pow(kDollyFactorPerViewport, -dy * perPixel));
      break;
    case DragMode::Pan: {
      // World units per pixel at the focal point, where the view shows 2 d tan(angle / 2) units
      // over its height (in both projections), so the focal plane sticks to the cursor.
      const double halfAngle = camera_.viewAngleDeg * kPi / 360.0;
      const double units = 2.0 * camera_.distance() * std::tan(halfAngle) * perPixel;
      camera_.pan(-dx * units, dy * units);
      break;
    }
    case DragMode::None:
      return false;
  }
  changed();
  return true;
}

void CameraController::scroll(double steps) {
  if (steps == 0.0) return;
  camera_.dolly(std::pow(kDollyFactorPerScrollStep, steps));
  changed();
}

void CameraController::reset() {
  camera_ = initial_;
  mode_ = DragMode::None;
  changed();
}

void CameraController::setCamera(const Camera& camera) {
  camera_ = camera;
  changed();
}

void CameraController::restart(const Camera& camera) {
  initial_ = camera;
  mode_ = DragMode::None;
  setCamera(camera);
}

}  // namespace ewa
