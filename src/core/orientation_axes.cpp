// The orientation axes: their strokes from the camera's rotation, a stroke alphabet for their
// labels, and an anti-aliased CPU painter for headless pictures.
#include "core/orientation_axes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace ewa {

namespace {

using Segment = std::array<glm::dvec2, 2>;

constexpr std::array<uint8_t, 3> kAxisColours[3] = {{235, 70, 60}, {80, 205, 80}, {90, 140, 255}};
constexpr std::array<uint8_t, 3> kOutline = {0, 0, 0};
constexpr double kOutlineOpacity = 0.6;

// Distance from p to the segment a-b.
double segmentDistance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

void paint(uint8_t* px, int channels, const std::array<uint8_t, 3>& rgb, double cover) {
  for (int c = 0; c < 3; ++c) px[c] = uint8_t(std::lround(px[c] + (rgb[c] - px[c]) * cover));
  if (channels == 4) px[3] = uint8_t(std::lround(px[3] + (255 - px[3]) * cover));
}

double letterHeight(double axisLength) {
  return std::max(8.0, 0.28 * axisLength);
}

// How far from the centre a label's strokes and their outline reach at most.
double axesReach(double axisLength) {
  const double h = letterHeight(axisLength);
  return axisLength + 0.85 * h + 0.5 * h + 2.0;
}

}  // namespace

AxesPlacement axesPlacement(int width, int height, double lift) {
  AxesPlacement p;
  // 7% of the picture's smaller side, 20 to 60 pixels, at most a fifth of it (small pictures).
  const double side = std::min(width, height);
  p.length = std::min(std::clamp(0.07 * side, 20.0, 60.0), 0.2 * side);
  const double room = axesReach(p.length);
  p.centre = glm::dvec2(width - room, height - room - lift);
  return p;
}

std::vector<Segment> letterStrokes(char letter) {
  using V = glm::dvec2;
  switch (letter) {
    case 'X':
      return {{V(0, 0), V(1, 1)}, {V(1, 0), V(0, 1)}};
    case 'Y':
      return {{V(0, 0), V(0.5, 0.5)}, {V(1, 0), V(0.5, 0.5)}, {V(0.5, 0.5), V(0.5, 1)}};
    case 'Z':
      return {{V(0, 0), V(1, 0)}, {V(1, 0), V(0, 1)}, {V(0, 1), V(1, 1)}};
    case 'L':
      return {{V(0, 0), V(0, 1)}, {V(0, 1), V(1, 1)}};
    case 'P':
      return {{V(0, 1), V(0, 0)},       {V(0, 0), V(0.7, 0)},      {V(0.7, 0), V(1, 0.15)},
              {V(1, 0.15), V(1, 0.35)}, {V(1, 0.35), V(0.7, 0.5)}, {V(0.7, 0.5), V(0, 0.5)}};
    case 'S':
      return {{V(1, 0.12), V(0.8, 0)},   {V(0.8, 0), V(0.2, 0)},    {V(0.2, 0), V(0, 0.15)},
              {V(0, 0.15), V(0, 0.33)},  {V(0, 0.33), V(0.2, 0.5)}, {V(0.2, 0.5), V(0.8, 0.5)},
              {V(0.8, 0.5), V(1, 0.67)}, {V(1, 0.67), V(1, 0.85)},  {V(1, 0.85), V(0.8, 1)},
              {V(0.8, 1), V(0.2, 1)},    {V(0.2, 1), V(0, 0.88)}};
    default:
      return {};
  }
}

std::vector<Stroke> orientationAxes(const glm::dmat3& rotation, bool patientFrame,
                                    const AxesPlacement& placement) {
  const char labels[2][3] = {{'X', 'Y', 'Z'}, {'L', 'P', 'S'}};
  // Back to front: the axis pointing furthest from the eye (most negative camera z) first.
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int a, int b) { return rotation[a].z < rotation[b].z; });
  const double axisWidth = std::max(1.5, placement.length / 25.0);
  const double height = letterHeight(placement.length), width = 0.7 * height;
  std::vector<Stroke> strokes;
  for (const int a : order) {
    // Column a of the rotation is world axis a in camera space; the picture's y runs down.
    const glm::dvec2 across(rotation[a].x, -rotation[a].y);
    const glm::dvec2 tip = placement.centre + placement.length * across;
    const double reach = glm::length(across);
    // An axis seen nearly end-on has no direction on screen: its label sits up and to the right.
    const glm::dvec2 out = reach > 0.15 ? across / reach : glm::dvec2(0.7071, -0.7071);
    const glm::dvec2 labelCentre = tip + out * (0.85 * height);
    const glm::dvec2 corner = labelCentre - 0.5 * glm::dvec2(width, height);
    std::vector<Stroke> shape;
    shape.push_back({placement.centre, tip, kAxisColours[a], axisWidth, 1.0});
    for (const Segment& s : letterStrokes(labels[patientFrame ? 1 : 0][a])) {
      const glm::dvec2 from = corner + s[0] * glm::dvec2(width, height);
      const glm::dvec2 to = corner + s[1] * glm::dvec2(width, height);
      shape.push_back({from, to, kAxisColours[a], 1.5, 1.0});
    }
    for (const Stroke& s : shape)
      strokes.push_back({s.from, s.to, kOutline, s.width + 2.0, kOutlineOpacity});
    strokes.insert(strokes.end(), shape.begin(), shape.end());
  }
  return strokes;
}

void drawStrokes(Image8& image, const std::vector<Stroke>& strokes) {
  const int channels = image.channels;
  if (image.width <= 0 || image.height <= 0 || (channels != 3 && channels != 4)) return;
  for (const Stroke& s : strokes) {
    const double half = 0.5 * s.width;
    const int x0 = std::max(0, int(std::floor(std::min(s.from.x, s.to.x) - half - 1.0)));
    const int x1 = std::min(image.width - 1, int(std::ceil(std::max(s.from.x, s.to.x) + half)));
    const int y0 = std::max(0, int(std::floor(std::min(s.from.y, s.to.y) - half - 1.0)));
    const int y1 = std::min(image.height - 1, int(std::ceil(std::max(s.from.y, s.to.y) + half)));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        // The share of a one-pixel box within the stroke, approximated by the distance of the
        // pixel's centre from the stroke's edge.
        const double d = segmentDistance(glm::dvec2(x + 0.5, y + 0.5), s.from, s.to);
        const double cover = std::clamp(half + 0.5 - d, 0.0, 1.0) * s.opacity;
        if (cover <= 0.0) continue;
        paint(&image.pixels[(size_t(y) * image.width + x) * channels], channels, s.rgb, cover);
      }
    }
  }
}

}  // namespace ewa
