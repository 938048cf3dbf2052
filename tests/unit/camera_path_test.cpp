// Unit tests of recorded camera paths and the standard axis views.
#include "core/camera_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/camera_views.h"

namespace ewa {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseCameraPath(text, "p.path");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(CameraPath, ParsesCommandsRepeatsAndComments) {
  const auto steps = parseCameraPath(
      "# a path\n3 orbit 5 -1\n\ndolly 1.5  # closer\npan 0.1 -0.2\nhold\n", "p.path");
  ASSERT_EQ(steps.size(), 6u);
  EXPECT_EQ(steps[0].kind, CameraStep::Kind::Orbit);
  EXPECT_EQ(steps[2].a, 5.0);
  EXPECT_EQ(steps[2].b, -1.0);
  EXPECT_EQ(steps[3].kind, CameraStep::Kind::Dolly);
  EXPECT_EQ(steps[3].a, 1.5);
  EXPECT_EQ(steps[4].kind, CameraStep::Kind::Pan);
  EXPECT_EQ(steps[4].b, -0.2);
  EXPECT_EQ(steps[5].kind, CameraStep::Kind::Hold);
}

TEST(CameraPath, BadLinesNameFileAndLine) {
  EXPECT_EQ(errorOf("orbit 1\n"), "p.path:1: orbit needs 2 numbers");
  EXPECT_EQ(errorOf("hold\nspin 3\n"), "p.path:2: unknown command 'spin'");
  EXPECT_EQ(errorOf("dolly 0\n"), "p.path:1: dolly factor must be positive");
  EXPECT_EQ(errorOf("0 hold\n"), "p.path:1: bad repeat count '0'");
  EXPECT_EQ(errorOf("orbit 1 2 3\n"), "p.path:1: unexpected '3' after orbit");
  EXPECT_EQ(errorOf("orbit nan 2\n"), "p.path:1: orbit needs 2 numbers");
  EXPECT_EQ(errorOf("# nothing\n"), "p.path: no camera steps");
  EXPECT_THROW(loadCameraPath("/no/such/path.txt"), std::runtime_error);
}

TEST(CameraPath, StepsMoveTheCamera) {
  Camera cam;
  cam.position = {0, 0, 10};
  Camera c = cam;
  applyCameraStep(c, {CameraStep::Kind::Orbit, 90.0, 0.0, Camera{}});
  EXPECT_NEAR(c.position.x, 10.0, 1e-9);
  EXPECT_NEAR(c.position.z, 0.0, 1e-9);
  c = cam;
  applyCameraStep(c, {CameraStep::Kind::Dolly, 2.0, 0.0, Camera{}});
  EXPECT_NEAR(c.distance(), 5.0, 1e-12);
  c = cam;
  applyCameraStep(c,
                  {CameraStep::Kind::Pan, 0.1, 0.0, Camera{}});  // a tenth of the distance, right
  EXPECT_NEAR(c.position.x, 1.0, 1e-12);
  EXPECT_NEAR(c.focalPoint.x, 1.0, 1e-12);
  c = cam;
  applyCameraStep(c, {CameraStep::Kind::Hold, 0.0, 0.0, Camera{}});
  EXPECT_EQ(c.position, cam.position);
}

TEST(CameraPath, RecordedCameraLinesRoundTripExactly) {
  Camera c;
  c.position = {1.0 / 3.0, -2.5e3, 7.0};
  c.focalPoint = {0.1, 0.2, 0.3};
  c.viewUp = {0.0, 0.0, 1.0};
  c.viewAngleDeg = 17.25;
  c.orthographic = true;
  const auto steps = parseCameraPath(cameraStepLine(c) + "\norbit 1 0\n", "rec.path");
  ASSERT_EQ(steps.size(), 2u);
  Camera replayed;
  applyCameraStep(replayed, steps[0]);
  EXPECT_EQ(replayed.position, c.position);
  EXPECT_EQ(replayed.focalPoint, c.focalPoint);
  EXPECT_EQ(replayed.viewUp, c.viewUp);
  EXPECT_EQ(replayed.viewAngleDeg, 17.25);
  EXPECT_TRUE(replayed.orthographic);
  EXPECT_EQ(errorOf("camera 0 0 0 0 0 0 0 1 0 30 0\n"), "p.path:1: camera is not a valid view");
  EXPECT_EQ(errorOf("camera 1 2 3\n"), "p.path:1: camera needs 11 numbers");
}

TEST(AxisViews, LookAlongEachAxisAtTheBoxCentre) {
  Camera cam;
  cam.viewAngleDeg = 40.0;
  cam.orthographic = true;
  const glm::dvec3 lo(0, 0, 0), hi(10, 20, 30);
  for (AxisView v : kAxisViews) {
    const Camera c = cameraForAxisView(cam, v, lo, hi, 1.0);
    EXPECT_TRUE(c.valid()) << axisViewName(v);
    EXPECT_NEAR(glm::length(c.direction() - axisViewDirection(v)), 0.0, 1e-12) << axisViewName(v);
    EXPECT_EQ(c.focalPoint, glm::dvec3(5, 10, 15));
    EXPECT_NEAR(glm::dot(glm::normalize(c.viewUp), axisViewUp(v)), 1.0, 1e-12);
    EXPECT_EQ(c.viewAngleDeg, 40.0);
    EXPECT_TRUE(c.orthographic);
    // Framed: the bounding sphere (radius |hi - lo| / 2) fits the view angle.
    EXPECT_NEAR(c.distance() * std::sin(glm::radians(20.0)), 0.5 * glm::length(hi - lo), 1e-9);
  }
  EXPECT_STREQ(axisViewName(AxisView::MinusY), "-Y");
}

TEST(AxisViews, TurntableFramesOrbitEvenlyAboutViewUp) {
  Camera start;
  start.position = {0, 0, 10};
  const Camera quarter = turntableCamera(start, 9, 36);  // 90 degrees
  EXPECT_NEAR(quarter.position.x, 10.0, 1e-9);
  EXPECT_NEAR(quarter.position.z, 0.0, 1e-9);
  EXPECT_NEAR(quarter.distance(), 10.0, 1e-9);
  EXPECT_EQ(turntableCamera(start, 0, 36).position, start.position);
  const Camera last = turntableCamera(start, 35, 36);  // one step short of the start
  EXPECT_NEAR(glm::length(last.position - start.position), 2 * 10 * std::sin(glm::radians(5.0)),
              1e-9);
}

}  // namespace
}  // namespace ewa
