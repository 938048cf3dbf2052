// Unit tests of the mouse-to-camera mapping of the interactive viewer (pure logic, no window).
#include "core/camera_controller.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

namespace ewa {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The eye on +z, 10 units from the origin, looking down -z with +y up.
Camera frontCamera() {
  Camera camera;
  camera.position = glm::dvec3(0.0, 0.0, 10.0);
  camera.focalPoint = glm::dvec3(0.0);
  camera.viewUp = glm::dvec3(0.0, 1.0, 0.0);
  camera.viewAngleDeg = 30.0;
  return camera;
}

CameraController controller(int width = 800, int height = 600) {
  CameraController c(frontCamera());
  c.setViewportSize(width, height);
  return c;
}

void drag(CameraController& c, MouseButton button, bool shift, double x0, double y0, double x1,
          double y1) {
  c.pressButton(button, shift, x0, y0);
  c.moveCursor(x1, y1);
  c.releaseButton(button);
}

TEST(CameraController, LeftDragRightSwingsTheEyeLeftAboutTheFocalPoint) {
  CameraController c = controller();
  drag(c, MouseButton::Left, false, 400, 300, 430, 300);
  EXPECT_LT(c.camera().position.x, -0.1);          // the grabbed surface follows the cursor
  EXPECT_NEAR(c.camera().position.y, 0.0, 1e-9);   // no elevation
  EXPECT_NEAR(c.camera().distance(), 10.0, 1e-9);  // an orbit keeps the distance
  EXPECT_EQ(c.camera().focalPoint, glm::dvec3(0.0));
  // 30 pixels of a 600-pixel-high viewport: 10 degrees.
  const double degrees = std::atan2(-c.camera().position.x, c.camera().position.z) * 180 / kPi;
  EXPECT_NEAR(degrees, 30.0 / 600.0 * CameraController::kOrbitDegreesPerViewport, 1e-9);
}

TEST(CameraController, LeftDragUpSwingsTheEyeDown) {
  CameraController c = controller();
  drag(c, MouseButton::Left, false, 400, 300, 400, 270);  // window y grows downwards
  EXPECT_LT(c.camera().position.y, -0.1);
  EXPECT_NEAR(c.camera().position.x, 0.0, 1e-9);
  EXPECT_NEAR(c.camera().distance(), 10.0, 1e-9);
  // View-up stays perpendicular to the view direction.
  EXPECT_NEAR(glm::dot(c.camera().viewUp, c.camera().direction()), 0.0, 1e-9);
}

TEST(CameraController, RightDragUpAndScrollUpMoveTheEyeCloser) {
  CameraController c = controller();
  drag(c, MouseButton::Right, false, 400, 300, 400, 150);
  EXPECT_NEAR(c.camera().distance(),
              10.0 / std::pow(CameraController::kDollyFactorPerViewport, 0.25), 1e-9);
  EXPECT_EQ(c.camera().focalPoint, glm::dvec3(0.0));

  CameraController s = controller();
  s.scroll(2.0);
  EXPECT_NEAR(s.camera().distance(), 10.0 / (1.1 * 1.1), 1e-9);
  s.scroll(-2.0);
  EXPECT_NEAR(s.camera().distance(), 10.0, 1e-9);
}

TEST(CameraController, PanMovesEyeAndFocalPointSoTheFocalPlaneFollowsTheCursor) {
  for (const bool middle : {true, false}) {
    CameraController c = controller();
    if (middle) {
      drag(c, MouseButton::Middle, false, 400, 300, 460, 330);
    } else {
      drag(c, MouseButton::Left, true, 400, 300, 460, 330);  // shift + left
    }
    // The view shows 2 * 10 * tan(15 deg) units over 600 pixels.
    const double unitsPerPixel = 20.0 * std::tan(15.0 * kPi / 180.0) / 600.0;
    EXPECT_NEAR(c.camera().focalPoint.x, -60.0 * unitsPerPixel, 1e-9);
    EXPECT_NEAR(c.camera().focalPoint.y, 30.0 * unitsPerPixel, 1e-9);
    EXPECT_NEAR(c.camera().position.x, c.camera().focalPoint.x, 1e-9);
    EXPECT_NEAR(c.camera().position.y, c.camera().focalPoint.y, 1e-9);
    EXPECT_NEAR(c.camera().distance(), 10.0, 1e-9);
  }
}

TEST(CameraController, MovesWithoutADragAndReleasedDragsDoNothing) {
  CameraController c = controller();
  const uint64_t start = c.revision();
  EXPECT_FALSE(c.moveCursor(500, 500));
  c.pressButton(MouseButton::Left, false, 400, 300);
  c.releaseButton(MouseButton::Left);
  EXPECT_FALSE(c.moveCursor(450, 350));
  EXPECT_EQ(c.revision(), start);
  EXPECT_EQ(c.camera().position, glm::dvec3(0.0, 0.0, 10.0));
}

TEST(CameraController, TheFirstButtonKeepsTheDrag) {
  CameraController c = controller();
  c.pressButton(MouseButton::Left, false, 400, 300);
  c.pressButton(MouseButton::Right, false, 400, 300);  // ignored: an orbit is running
  EXPECT_EQ(c.dragMode(), DragMode::Orbit);
  c.releaseButton(MouseButton::Right);  // not the drag's button
  EXPECT_TRUE(c.dragging());
  EXPECT_TRUE(c.moveCursor(420, 300));
  EXPECT_NEAR(c.camera().distance(), 10.0, 1e-9);
  c.releaseButton(MouseButton::Left);
  EXPECT_FALSE(c.dragging());
}

TEST(CameraController, ResetRestoresTheInitialCameraAndCountsAsAChange) {
  CameraController c = controller();
  drag(c, MouseButton::Left, false, 400, 300, 480, 250);
  c.scroll(3.0);
  Camera edited = c.camera();
  edited.orthographic = true;
  c.setCamera(edited);
  EXPECT_TRUE(c.camera().orthographic);
  const uint64_t before = c.revision();
  c.reset();
  EXPECT_GT(c.revision(), before);
  EXPECT_EQ(c.camera().position, frontCamera().position);
  EXPECT_EQ(c.camera().viewUp, frontCamera().viewUp);
  EXPECT_FALSE(c.camera().orthographic);
}

TEST(CameraController, DragsScaleWithTheViewportHeight) {
  CameraController small = controller(400, 300);
  CameraController large = controller(800, 600);
  drag(small, MouseButton::Left, false, 0, 0, 15, 0);
  drag(large, MouseButton::Left, false, 0, 0, 30, 0);
  EXPECT_NEAR(glm::length(small.camera().position - large.camera().position), 0.0, 1e-9);
}

}  // namespace
}  // namespace ewa
