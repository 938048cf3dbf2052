// The orientation axes: where each axis points as the camera turns, their labels and drawing
// order, and the anti-aliased stroke painter.
#include "core/orientation_axes.h"

#include <gtest/gtest.h>

#include "core/camera.h"

namespace ewa {
namespace {

constexpr std::array<uint8_t, 3> kRed = {235, 70, 60}, kGreen = {80, 205, 80},
                                 kBlue = {90, 140, 255};

Camera lookingAt(glm::dvec3 eye, glm::dvec3 up) {
  Camera c;
  c.position = eye;
  c.focalPoint = glm::dvec3(0.0);
  c.viewUp = up;
  return c;
}

// The axis line of one colour: its first stroke of that colour (the label's follow it).
const Stroke& axisOf(const std::vector<Stroke>& strokes, const std::array<uint8_t, 3>& rgb) {
  for (const Stroke& s : strokes)
    if (s.rgb == rgb && s.opacity == 1.0) return s;
  throw std::runtime_error("no stroke of that colour");
}

size_t countOf(const std::vector<Stroke>& strokes, const std::array<uint8_t, 3>& rgb) {
  size_t n = 0;
  for (const Stroke& s : strokes) n += s.rgb == rgb;
  return n;
}

TEST(OrientationAxes, AxesPointWhereTheCameraSeesThem) {
  // From -y with z up: x to the right, z up the picture, y straight into it (end-on).
  const AxesPlacement at{glm::dvec2(100.0, 80.0), 40.0};
  const auto strokes = orientationAxes(lookingAt({0, -10, 0}, {0, 0, 1}).rotation(), false, at);
  const Stroke& x = axisOf(strokes, kRed);
  const Stroke& y = axisOf(strokes, kGreen);
  const Stroke& z = axisOf(strokes, kBlue);
  EXPECT_EQ(x.from, at.centre);
  EXPECT_NEAR(x.to.x, 140.0, 1e-9);
  EXPECT_NEAR(x.to.y, 80.0, 1e-9);
  EXPECT_NEAR(z.to.x, 100.0, 1e-9);
  EXPECT_NEAR(z.to.y, 40.0, 1e-9);  // up the picture: smaller y
  EXPECT_NEAR(glm::length(y.to - y.from), 0.0, 1e-9);
  // Turned a quarter about z (from +x): y to the right, x straight out of the picture.
  const auto turned = orientationAxes(lookingAt({10, 0, 0}, {0, 0, 1}).rotation(), false, at);
  EXPECT_NEAR(axisOf(turned, kGreen).to.x, 140.0, 1e-9);
  EXPECT_NEAR(glm::length(axisOf(turned, kRed).to - at.centre), 0.0, 1e-9);
}

TEST(OrientationAxes, PatientAxesAreLabelledLeftPosteriorSuperior) {
  const AxesPlacement at{glm::dvec2(60.0, 60.0), 30.0};
  const glm::dmat3 r = lookingAt({3, -10, 4}, {0, 0, 1}).rotation();
  const auto plain = orientationAxes(r, false, at), patient = orientationAxes(r, true, at);
  // Each axis is its line and its letter's strokes, each drawn over a dark outline.
  EXPECT_EQ(countOf(plain, kRed), 1 + letterStrokes('X').size());
  EXPECT_EQ(countOf(plain, kGreen), 1 + letterStrokes('Y').size());
  EXPECT_EQ(countOf(plain, kBlue), 1 + letterStrokes('Z').size());
  EXPECT_EQ(countOf(patient, kRed), 1 + letterStrokes('L').size());
  EXPECT_EQ(countOf(patient, kGreen), 1 + letterStrokes('P').size());
  EXPECT_EQ(countOf(patient, kBlue), 1 + letterStrokes('S').size());
  EXPECT_EQ(patient.size(), 2 * (3 + letterStrokes('L').size() + letterStrokes('P').size() +
                                 letterStrokes('S').size()));
  for (char c : {'X', 'Y', 'Z', 'L', 'P', 'S'}) EXPECT_FALSE(letterStrokes(c).empty()) << c;
  EXPECT_TRUE(letterStrokes('Q').empty());
  // The label lies beyond the tip of its axis, not across the picture.
  const Stroke& x = axisOf(plain, kRed);
  for (const Stroke& s : plain) {
    if (s.rgb != kRed || &s == &x) continue;
    EXPECT_GT(glm::dot(s.from - at.centre, x.to - at.centre),
              0.5 * glm::dot(x.to - at.centre, x.to - at.centre));
  }
}

TEST(OrientationAxes, TheAxisNearestTheEyeIsDrawnLast) {
  // Eye mostly along +x, a little toward -y: x nearest, y furthest.
  const auto strokes = orientationAxes(lookingAt({10, -5, 2}, {0, 0, 1}).rotation(), false,
                                       AxesPlacement{glm::dvec2(50.0), 20.0});
  EXPECT_EQ(strokes.back().rgb, kRed);
  size_t firstColoured = 0;
  while (strokes[firstColoured].opacity != 1.0) ++firstColoured;
  EXPECT_EQ(strokes[firstColoured].rgb, kGreen);
  EXPECT_EQ(strokes.front().opacity, 0.6);  // the outline under the furthest axis
}

TEST(OrientationAxes, PlacementKeepsTheAxesAndLabelsInsideTheCorner) {
  for (const glm::ivec2 size : {glm::ivec2(64, 64), glm::ivec2(400, 300), glm::ivec2(1920, 1080)}) {
    const AxesPlacement p = axesPlacement(size.x, size.y, 10.0);
    EXPECT_GE(p.length, std::min(20.0, 0.2 * size.y));
    EXPECT_LE(p.length, 60.0);
    // Any direction: every stroke stays in the picture, in its lower right part.
    for (const glm::dvec3 eye :
         {glm::dvec3(1, -3, 2), glm::dvec3(-2, 1, -4), glm::dvec3(0, 0, 5)}) {
      for (const Stroke& s : orientationAxes(lookingAt(eye, {0, 1, 0.3}).rotation(), true, p)) {
        for (const glm::dvec2 q : {s.from, s.to}) {
          EXPECT_GE(q.x - 0.5 * s.width, std::max(0.0, 0.5 * size.x - 40.0)) << size.x;
          EXPECT_LE(q.x + 0.5 * s.width, size.x);
          EXPECT_GE(q.y - 0.5 * s.width, std::max(0.0, 0.5 * size.y - 40.0)) << size.y;
          EXPECT_LE(q.y + 0.5 * s.width, size.y - 10.0);
        }
      }
    }
  }
}

TEST(OrientationAxes, StrokesPaintTheirShareOfEachPixel) {
  Image8 image{20, 20, 4, std::vector<uint8_t>(20 * 20 * 4, 0)};
  // Horizontal, 3 pixels wide, along y = 10: rows 9 and 10 lie inside, rows 8 and 11 half.
  drawStrokes(image, {{glm::dvec2(2.0, 10.0), glm::dvec2(18.0, 10.0), {200, 100, 0}, 3.0, 1.0}});
  auto at = [&](int x, int y) { return &image.pixels[size_t(y * 20 + x) * 4]; };
  EXPECT_EQ(at(10, 10)[0], 200);
  EXPECT_EQ(at(10, 10)[1], 100);
  EXPECT_EQ(at(10, 10)[3], 255);
  EXPECT_EQ(at(10, 9)[0], 200);
  EXPECT_EQ(at(10, 11)[0], 100);  // centre 1.5 from the line: half covered
  EXPECT_EQ(at(10, 11)[3], 128);
  EXPECT_EQ(at(10, 13)[0], 0);
  EXPECT_GT(at(0, 10)[0], 0);  // the round end's edge: 1.58 from (2, 10), partly covered
  EXPECT_LT(at(0, 10)[0], 200);
  // Opacity scales the share; a second stroke blends over the first.
  drawStrokes(image, {{glm::dvec2(10.5, 0.0), glm::dvec2(10.5, 20.0), {0, 0, 255}, 1.0, 0.5}});
  EXPECT_EQ(at(10, 10)[2], 128);
  EXPECT_EQ(at(10, 10)[0], 100);
  // RGB pictures, and strokes off the picture, are fine.
  Image8 rgb{8, 8, 3, std::vector<uint8_t>(8 * 8 * 3, 10)};
  drawStrokes(rgb, {{glm::dvec2(-50.0, -50.0), glm::dvec2(-40.0, -40.0), {255, 0, 0}, 2.0, 1.0}});
  EXPECT_EQ(rgb.pixels, std::vector<uint8_t>(8 * 8 * 3, 10));
}

}  // namespace
}  // namespace ewa
