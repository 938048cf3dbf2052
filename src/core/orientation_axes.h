// The orientation axes drawn in a picture's corner: the world's axes as the camera turns them,
// as strokes that the window (ImGui) and headless pictures (drawStrokes) both draw.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <vector>

#include "core/image8.h"

namespace ewa {

// One straight stroke in pixels (x right, y down, the picture's top-left corner at 0, 0).
struct Stroke {
  glm::dvec2 from{0.0}, to{0.0};
  std::array<uint8_t, 3> rgb{};
  double width = 1.0;    // pixels
  double opacity = 1.0;  // 0 to 1
};

// Where the axes go in a width x height picture: their centre and an axis's length across the
// view, in pixels. The bottom-right corner, `lift` pixels higher (the window keeps its probe
// line below them).
struct AxesPlacement {
  glm::dvec2 centre{0.0};
  double length = 0.0;
};
AxesPlacement axesPlacement(int width, int height, double lift = 0.0);

// The world's three axes from `placement.centre`, each `placement.length` pixels long where it
// lies across the view (shorter as it turns toward or away from the eye), labelled at its
// positive end: X, Y, Z, or for patient axes (LPS) L, P, S, the patient's left, back and head.
// Red, green and blue, each over a dark outline so it shows on any background; the axis
// nearest the eye comes last, so drawing the strokes in order paints it on top. `rotation` is
// Camera::rotation() (world to camera space: x right, y up, the eye looking down -z).
std::vector<Stroke> orientationAxes(const glm::dmat3& rotation, bool patientFrame,
                                    const AxesPlacement& placement);

// A capital letter as line segments in a unit box (x right, y down, 0 to 1); empty for any
// letter the axes do not use (only X, Y, Z, L, P and S are drawn).
std::vector<std::array<glm::dvec2, 2>> letterStrokes(char letter);

// Paints `strokes` in order over `image` (3 or 4 channels), anti-aliased: each pixel takes the
// share of it a stroke of round ends covers, times the stroke's opacity.
void drawStrokes(Image8& image, const std::vector<Stroke>& strokes);

}  // namespace ewa
