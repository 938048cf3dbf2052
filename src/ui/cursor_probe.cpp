// CursorProbe: the pick under the cursor, recomputed only when something it depends on changed.
#include "ui/cursor_probe.h"

#include <imgui.h>

#include <cstdio>
#include <utility>

#include "render/renderer.h"

namespace ewa {

std::string probeText(const Volume& volume, const PickResult& pick) {
  if (!pick.hit) return "";
  const glm::i64vec3 voxel = nearestVoxel(volume, pick.index);
  char text[160];
  std::snprintf(text, sizeof text, "x %.4g  y %.4g  z %.4g   voxel %lld, %lld, %lld   value %.6g",
                pick.world.x, pick.world.y, pick.world.z, (long long)voxel.x, (long long)voxel.y,
                (long long)voxel.z, pick.value);
  return text;
}

void CursorProbe::update(const Volume& volume, const TransferFunction& tf,
                         const RenderSettings& settings, const Camera& camera,
                         glm::ivec2 windowSize, std::optional<glm::dvec2> cursor,
                         const ProbeStamp& stamp) {
  changed_ = false;
  if (!cursor || windowSize.x <= 0 || windowSize.y <= 0) {
    shown_ = false;
    changed_ = !text_.empty();
    text_.clear();
    return;
  }
  if (shown_ && *cursor == cursor_ && stamp == stamp_) return;
  const PickResult pick =
      pickVolume(volume, tf, settings.clip, pickRay(camera, windowSize.x, windowSize.y, *cursor),
                 pickRuleFor(settings.mode));
  std::string text = probeText(volume, pick);
  changed_ = text != text_;
  text_ = std::move(text);
  shown_ = true;
  cursor_ = *cursor;
  stamp_ = stamp;
}

void CursorProbe::draw(bool lifted) const {
  if (text_.empty()) return;
  const ImGuiViewport* view = ImGui::GetMainViewport();
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text_.c_str());
  // Bottom right, where the default layout leaves the picture uncovered; above the progress bar.
  const float lift = lifted ? size.y + 8.0f : 0.0f;
  const ImVec2 at(view->Pos.x + view->Size.x - size.x - 12.0f,
                  view->Pos.y + view->Size.y - size.y - 10.0f - lift);
  draw->AddRectFilled(ImVec2(at.x - 4.0f, at.y - 2.0f),
                      ImVec2(at.x + size.x + 4.0f, at.y + size.y + 2.0f), IM_COL32(0, 0, 0, 160),
                      3.0f);
  draw->AddText(at, IM_COL32(230, 230, 230, 255), text_.c_str());
}

}  // namespace ewa
