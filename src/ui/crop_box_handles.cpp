// Crop box overlay: edges on ImGui's background draw list, face handles as tiny windows.
#include "ui/crop_box_handles.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <glm/geometric.hpp>
#include <optional>

#include "core/volume_pick.h"

namespace ewa {

namespace {

constexpr float kHandleSize = 14.0f;
const char* const kAxisNames[] = {"x", "y", "z"};

}  // namespace

CropHandleEdits drawCropBoxHandles(ClipRegion& region, const Camera& camera, double minThickness) {
  CropHandleEdits edits;
  if (!region.cropEnabled) return edits;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  if (display.x < 1.0f || display.y < 1.0f) return edits;
  // Display position (ImGui: y down) of a world point, or nothing behind the eye.
  const auto toScreen = [&](const glm::dvec3& world) -> std::optional<ImVec2> {
    const auto at = windowPoint(camera, int(display.x), int(display.y), world);
    if (!at) return std::nullopt;
    return ImVec2(float(at->x), float(at->y));
  };
  const glm::dvec3 lo = region.cropMin, hi = region.cropMax;
  ImDrawList* lines = ImGui::GetBackgroundDrawList();
  const ImU32 edgeColour = IM_COL32(255, 220, 80, 160);
  for (int c = 0; c < 8; ++c)
    for (int a = 0; a < 3; ++a) {
      if (c & (1 << a)) continue;  // each edge once, from its low corner
      const int d = c | (1 << a);
      const auto corner = [&](int k) {
        return glm::dvec3((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
      };
      const auto p = toScreen(corner(c)), q = toScreen(corner(d));
      if (p && q) lines->AddLine(*p, *q, edgeColour, 1.5f);
    }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  for (int face = 0; face < 6; ++face) {
    const int axis = face / 2;
    const bool upper = face % 2 == 1;
    glm::dvec3 at = centre;
    at[axis] = upper ? hi[axis] : lo[axis];
    const auto screen = toScreen(at);
    if (!screen) continue;
    // The face's axis on screen: a world step of `step` moves the handle by `along` pixels.
    const double step = std::max(hi[axis] - lo[axis], 1e-9) * 0.01;
    glm::dvec3 further = at;
    further[axis] += step;
    const auto next = toScreen(further);
    if (!next) continue;
    const ImVec2 along(next->x - screen->x, next->y - screen->y);
    const float alongSq = along.x * along.x + along.y * along.y;
    char name[32];
    std::snprintf(name, sizeof name, "##crop face %d", face);
    ImGui::SetNextWindowPos(ImVec2(screen->x - 0.5f * kHandleSize, screen->y - 0.5f * kHandleSize));
    ImGui::SetNextWindowSize(ImVec2(kHandleSize, kHandleSize));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
    ImGui::Begin(name, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                     ImGuiWindowFlags_NoNav);
    ImGui::InvisibleButton("handle", ImVec2(kHandleSize, kHandleSize));
    const bool active = ImGui::IsItemActive(), hovered = ImGui::IsItemHovered();
    ImGui::GetWindowDrawList()->AddCircleFilled(
        *screen, 0.5f * kHandleSize - 2.0f,
        active || hovered ? IM_COL32(255, 240, 150, 255) : IM_COL32(255, 200, 60, 220));
    if (hovered && !active)
      ImGui::SetTooltip("drag: move the crop box's %s %s face", kAxisNames[axis],
                        upper ? "max" : "min");
    if (active) edits.dragging = true;
    // Not in the frame of the press: its delta may hold the cursor's jump onto the handle.
    if (active && !ImGui::IsItemActivated() && alongSq > 1e-6f) {
      const ImVec2 delta = ImGui::GetIO().MouseDelta;
      const double move = double(delta.x * along.x + delta.y * along.y) / alongSq * step;
      if (move != 0.0) {
        const double thick = std::max(minThickness, 0.0);
        if (upper)
          region.cropMax[axis] =
              std::max(region.cropMax[axis] + move, region.cropMin[axis] + thick);
        else
          region.cropMin[axis] =
              std::min(region.cropMin[axis] + move, region.cropMax[axis] - thick);
        edits.changed = true;
      }
    }
    ImGui::End();
    ImGui::PopStyleVar(3);
  }
  return edits;
}

}  // namespace ewa
