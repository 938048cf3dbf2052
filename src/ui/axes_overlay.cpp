// The orientation axes over the window's picture, through ImGui's background draw list.
#include "ui/axes_overlay.h"

#include <imgui.h>

#include <cmath>

#include "core/camera.h"
#include "core/orientation_axes.h"

namespace ewa {

void drawAxesOverlay(const Camera& camera, bool patientFrame, glm::ivec2 windowSize) {
  // Two text lines stay free below them: the probe line and the refinement's label.
  const double lift = 2.0 * ImGui::GetTextLineHeightWithSpacing() + 4.0;
  const AxesPlacement placement = axesPlacement(windowSize.x, windowSize.y, lift);
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  for (const Stroke& s : orientationAxes(camera.rotation(), patientFrame, placement)) {
    const ImU32 colour = IM_COL32(s.rgb[0], s.rgb[1], s.rgb[2], int(std::lround(255 * s.opacity)));
    draw->AddLine(ImVec2(float(s.from.x), float(s.from.y)), ImVec2(float(s.to.x), float(s.to.y)),
                  colour, float(s.width));
  }
}

}  // namespace ewa
