// Camera tours: the stops themselves at their frames, smooth legs between them.
#include "core/camera_tour.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace ewa {
namespace {

Camera cameraAt(glm::dvec3 position, glm::dvec3 focal, glm::dvec3 up, double angle = 30.0) {
  Camera c;
  c.position = position;
  c.focalPoint = focal;
  c.viewUp = up;
  c.viewAngleDeg = angle;
  return c;
}

void expectSameView(const Camera& a, const Camera& b) {
  EXPECT_NEAR(glm::distance(a.position, b.position), 0.0, 1e-9);
  EXPECT_NEAR(glm::distance(a.focalPoint, b.focalPoint), 0.0, 1e-9);
  // The stored up may be any vector in the plane of the true up: compare the orientation.
  const glm::dmat3 ra = a.rotation(), rb = b.rotation();
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(glm::distance(ra[c], rb[c]), 0.0, 1e-9);
  EXPECT_NEAR(a.viewAngleDeg, b.viewAngleDeg, 1e-12);
  EXPECT_EQ(a.orthographic, b.orthographic);
}

std::vector<TourStop> threeStops() {
  TourStop a{cameraAt({0, 0, 100}, {0, 0, 0}, {0, 1, 0}, 30.0), {}};
  TourStop b{cameraAt({50, 0, 0}, {10, 0, 0}, {0, 1, 0}, 20.0), {}};     // a quarter turn about y
  TourStop c{cameraAt({0, -400, 0}, {0, 0, 5}, {0, 0.5, 1}, 40.0), {}};  // up not orthogonal
  b.clip.cropEnabled = c.clip.cropEnabled = true;
  b.clip.cropMin = {0, 0, 0};
  b.clip.cropMax = {10, 10, 10};
  c.clip.cropMin = {2, 4, 6};
  c.clip.cropMax = {12, 14, 16};
  c.camera.orthographic = true;
  return {a, b, c};
}

TEST(CameraTour, FramesPassThroughEveryStop) {
  const auto stops = threeStops();
  // Five frames over two legs: frames 0, 2 and 4 are the stops.
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE(i);
    const TourStop s = tourFrame(stops, 2 * i, 5);
    expectSameView(s.camera, stops[size_t(i)].camera);
    EXPECT_EQ(s.clip.cropEnabled, stops[size_t(i)].clip.cropEnabled);
  }
  expectSameView(tourFrame(stops, 0, 1).camera, stops[0].camera);
  expectSameView(tourStop(stops, -3.0).camera, stops[0].camera);  // clamped
  expectSameView(tourStop(stops, 7.0).camera, stops[2].camera);
  EXPECT_THROW(tourStop({}, 0.5), std::invalid_argument);
}

TEST(CameraTour, ALegTurnsZoomsAndMovesSmoothly) {
  const auto stops = threeStops();
  // Half way along the first leg (eased: still half way): the focal point half way, the
  // distance the geometric mean, the eye turned half way (45 degrees about y), the angle 25.
  const Camera m = tourStop(stops, 0.25).camera;
  EXPECT_NEAR(glm::distance(m.focalPoint, glm::dvec3(5, 0, 0)), 0.0, 1e-9);
  EXPECT_NEAR(m.distance(), std::sqrt(100.0 * 40.0), 1e-9);
  EXPECT_NEAR(glm::dot(m.direction(), glm::normalize(glm::dvec3(1, 0, 1)) * -1.0), 1.0, 1e-9);
  EXPECT_NEAR(m.viewAngleDeg, 25.0, 1e-12);
  EXPECT_FALSE(m.orthographic);
  // Eased: slow near the stops, so a small step there moves the eye less than mid leg.
  const double nearStop =
      glm::distance(tourStop(stops, 0.0).camera.position, tourStop(stops, 0.01).camera.position);
  const double midLeg =
      glm::distance(tourStop(stops, 0.25).camera.position, tourStop(stops, 0.26).camera.position);
  EXPECT_LT(nearStop, 0.2 * midLeg);
  // Every view along the way is a valid camera.
  for (int f = 0; f <= 40; ++f) EXPECT_TRUE(tourFrame(stops, f, 41).camera.valid()) << f;
}

TEST(CameraTour, TheCropBoxMovesBetweenTwoBoxesAndOrthographicSwitchesHalfWay) {
  const auto stops = threeStops();
  const TourStop q = tourStop(stops, 0.75);  // half way along the second leg
  ASSERT_TRUE(q.clip.cropEnabled);
  EXPECT_NEAR(glm::distance(q.clip.cropMin, glm::dvec3(1, 2, 3)), 0.0, 1e-12);
  EXPECT_NEAR(glm::distance(q.clip.cropMax, glm::dvec3(11, 12, 13)), 0.0, 1e-12);
  EXPECT_FALSE(tourStop(stops, 0.74).camera.orthographic);
  EXPECT_TRUE(tourStop(stops, 0.76).camera.orthographic);
  // From no box to a box: the box appears half way along the first leg.
  EXPECT_FALSE(tourStop(stops, 0.24).clip.cropEnabled);
  EXPECT_TRUE(tourStop(stops, 0.26).clip.cropEnabled);
}

}  // namespace
}  // namespace ewa
