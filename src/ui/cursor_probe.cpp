// CursorProbe: the pick under the cursor, recomputed only when something it depends on changed.
#include "ui/cursor_probe.h"

#include <imgui.h>

#include <cstdio>
#include <utility>

#include "render/renderer.h"

namespace ewa {

void CursorProbe::update(const Volume& volume, const TransferFunction& tf,
                         const RenderSettings& settings, const Camera& camera,
                         glm::ivec2 windowSize, std::optional<glm::dvec2> cursor,
                         const ProbeStamp& stamp) {
  changed_ = false;
  if (!cursor || windowSize.x <= 0 || windowSize.y <= 0) {
    shown_ = false;
    last_ = PickResult();
    changed_ = !text_.empty();
    text_.clear();
    return;
  }
  if (shown_ && *cursor == cursor_ && stamp == stamp_) return;
  last_ = pickInPicture(volume, tf, settings, camera, windowSize.x, windowSize.y, *cursor);
  std::string text = describePick(volume, last_, mark_);
  changed_ = text != text_;
  text_ = std::move(text);
  shown_ = true;
  cursor_ = *cursor;
  stamp_ = stamp;
}

void CursorProbe::setMark(std::optional<glm::dvec3> mark) {
  mark_ = mark;
  shown_ = false;  // the text changes with it
}

void CursorProbe::draw(bool lifted, const Camera& camera, glm::ivec2 windowSize) const {
  const ImGuiViewport* view = ImGui::GetMainViewport();
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  if (mark_ && windowSize.x > 0 && windowSize.y > 0) {
    // The mark where the camera sees it, when it lies in front of the eye.
    if (const auto at = windowPoint(camera, windowSize.x, windowSize.y, *mark_)) {
      const ImVec2 centre(view->Pos.x + float(at->x), view->Pos.y + float(at->y));
      draw->AddCircle(centre, 6.0f, IM_COL32(0, 0, 0, 200), 16, 3.0f);
      draw->AddCircle(centre, 6.0f, IM_COL32(255, 220, 60, 255), 16, 1.5f);
    }
  }
  if (text_.empty()) return;
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
