// The orientation axes over the window's picture: the strokes of core/orientation_axes drawn
// with ImGui, in the bottom-right corner above the probe line.
#pragma once

#include <glm/vec2.hpp>

namespace ewa {

class Camera;

// Draws the world's axes as `camera` turns them (L, P, S for patient axes) behind the panels.
void drawAxesOverlay(const Camera& camera, bool patientFrame, glm::ivec2 windowSize);

}  // namespace ewa
