// CameraController: turns mouse drags and scrolls into camera orbit, dolly and pan (no GL, no UI).
#pragma once

#include <cstdint>

#include "core/camera.h"

namespace ewa {

enum class MouseButton { Left, Middle, Right };

// What the drag in progress does to the camera.
enum class DragMode { None, Orbit, Pan, Dolly };

class CameraController {
 public:
  // Degrees of orbit for a drag across the whole viewport height (VTK's trackball uses 200).
  static constexpr double kOrbitDegreesPerViewport = 200.0;
  // A drag across the whole viewport height dollies by this factor (up moves closer).
  static constexpr double kDollyFactorPerViewport = 8.0;
  // One scroll notch moves the eye this factor closer to the focal point.
  static constexpr double kDollyFactorPerScrollStep = 1.1;

  explicit CameraController(const Camera& initial);

  // Size of the area the cursor coordinates refer to (window coordinates, y down): it turns
  // pixels of mouse motion into angles and world units.
  void setViewportSize(int width, int height);

  // Starts a drag at cursor (x, y): left orbits, shift+left or middle pans, right dollies.
  // A press while another drag runs is ignored (the first button keeps control).
  void pressButton(MouseButton button, bool shift, double x, double y);
  // Ends the drag that `button` started; other buttons are ignored.
  void releaseButton(MouseButton button);
  // Cursor moved to (x, y); applies the running drag. Returns true when the camera changed.
  bool moveCursor(double x, double y);
  // Scroll wheel: positive steps (away from the user) move the eye closer.
  void scroll(double steps);

  // Back to the camera given at construction; ends any drag.
  void reset();
  // Replaces the camera (e.g. edited in the panel) and keeps the initial one for reset().
  void setCamera(const Camera& camera);
  // Replaces both the camera and the one reset() returns to (a new volume was opened).
  void restart(const Camera& camera);

  const Camera& camera() const { return camera_; }
  const Camera& initialCamera() const { return initial_; }
  DragMode dragMode() const { return mode_; }
  bool dragging() const { return mode_ != DragMode::None; }
  // Increases on every camera change, so a viewer can tell whether to render again.
  uint64_t revision() const { return revision_; }

 private:
  void changed() { ++revision_; }

  Camera initial_;
  Camera camera_;
  int width_ = 1;
  int height_ = 1;
  DragMode mode_ = DragMode::None;
  MouseButton dragButton_ = MouseButton::Left;
  double lastX_ = 0.0;
  double lastY_ = 0.0;
  uint64_t revision_ = 0;
};

}  // namespace ewa
