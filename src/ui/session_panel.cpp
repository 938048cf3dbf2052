// SessionPanel: open/recent files, camera bookmarks, screenshot and turntable, progress, messages.
#include "ui/session_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace ewa {

namespace {
const ImVec4 kErrorColor(1.0f, 0.45f, 0.4f, 1.0f);
const ImVec4 kInfoColor(0.6f, 0.9f, 0.6f, 1.0f);
}  // namespace

void SessionPanel::drawCaptures(const SessionView& view, SessionEdits& edits) {
  drawBookmarks(view, edits);
  drawCapture(view, edits);
}

void SessionPanel::drawStatus(const SessionView& view) {
  if (view.loading) {
    ImGui::Separator();
    ImGui::Text("Loading %s", std::filesystem::path(view.loadingPath).filename().c_str());
    // No byte counts come from the loaders: an animated bar with the elapsed time.
    const float phase = float(std::fmod(view.loadingSeconds, 2.0) / 2.0);
    char label[32];
    std::snprintf(label, sizeof label, "%.1f s", view.loadingSeconds);
    ImGui::ProgressBar(phase, ImVec2(-1.0f, 0.0f), label);
  }
  if (!view.busyText.empty()) ImGui::TextColored(kInfoColor, "%s", view.busyText.c_str());
  if (view.messages) {
    // Wrapped, so a long path does not stretch the auto-sized panel across the window.
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 380.0f);
    for (const StatusMessages::Message& m : *view.messages)
      ImGui::TextColored(m.kind == StatusMessages::Kind::Error ? kErrorColor : kInfoColor, "%s",
                         m.text.c_str());
    ImGui::PopTextWrapPos();
  }
}

void SessionPanel::drawFiles(const SessionView& view, SessionEdits& edits) {
  const bool open = ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen);
  layout_.lastItem("section-file");
  if (!open) return;
  edits.openDialog = ImGui::Button("Open... (Ctrl+O)");
  ImGui::SameLine();
  edits.saveDialog = ImGui::Button("Save volume... (Ctrl+S)");
  ImGui::TextDisabled("or drop a file on the window to open it");
  if (view.fromFile) {
    edits.reload = ImGui::Button("Reload (F5)");
    ImGui::SameLine();
    bool watching = view.watching;
    if (ImGui::Checkbox("reload when the file changes", &watching)) edits.watch = watching;
  }
  if (view.recentFiles && !view.recentFiles->empty() && ImGui::TreeNode("Recent files")) {
    for (const std::string& f : *view.recentFiles) {
      if (ImGui::Selectable(f.c_str())) edits.openPath = f;
    }
    ImGui::TreePop();
  }
}

void SessionPanel::drawBookmarks(const SessionView& view, SessionEdits& edits) {
  const bool open = ImGui::CollapsingHeader("Camera bookmarks");
  layout_.lastItem("section-bookmarks");
  if (!open) return;
  if (view.bookmarks) {
    for (int n = 0; n < int(view.bookmarks->size()); ++n) {
      ImGui::PushID(n);
      if (ImGui::Button((*view.bookmarks)[size_t(n)].name.c_str())) edits.applyBookmark = n;
      ImGui::SameLine();
      if (ImGui::SmallButton("x")) edits.deleteBookmark = n;
      ImGui::PopID();
    }
  }
  ImGui::SetNextItemWidth(150.0f);
  const bool enter = ImGui::InputText("##name", bookmarkName_, sizeof bookmarkName_,
                                      ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Add view") || enter) && bookmarkName_[0] != '\0') {
    edits.addBookmark = std::string(bookmarkName_);
    const int next = view.bookmarks ? int(view.bookmarks->size()) + 2 : 2;
    std::snprintf(bookmarkName_, sizeof bookmarkName_, "view %d", next);
  }
  if (!view.bookmarksPath.empty()) ImGui::TextDisabled("%s", view.bookmarksPath.c_str());
}

void SessionPanel::drawCapture(const SessionView& view, SessionEdits& edits) {
  const bool open = ImGui::CollapsingHeader("Capture");
  layout_.lastItem("capture-header");
  if (!open) return;
  edits.screenshot = ImGui::Button("Screenshot (F12)");
  layout_.lastItem("screenshot-button");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(110.0f);
  int scale = view.captureScale - 1;
  if (ImGui::Combo("size", &scale,
                   "window size\0"
                   "2x window\0"
                   "3x window\0"
                   "4x window\0"))
    edits.captureScale = scale + 1;
  if (view.turntableTotal > 0) {
    char label[48];
    std::snprintf(label, sizeof label, "turntable %d / %d", view.turntableDone,
                  view.turntableTotal);
    ImGui::ProgressBar(float(view.turntableDone) / float(view.turntableTotal), ImVec2(200.0f, 0.0f),
                       label);
    ImGui::SameLine();
    edits.cancelTurntable = ImGui::Button("Cancel");
    return;
  }
  ImGui::SetNextItemWidth(90.0f);
  ImGui::InputInt("frames", &turntableFrames_);
  if (turntableFrames_ < 1) turntableFrames_ = 1;
  if (turntableFrames_ > 3600) turntableFrames_ = 3600;
  // The formats --turntable writes: a folder of PNGs, or a video through FFmpeg.
  static constexpr const char* kFormats[] = {"png", "mp4", "webm"};
  ImGui::SetNextItemWidth(100.0f);
  ImGui::Combo("##format", &turntableFormat_, "PNG frames\0MP4\0WebM\0");
  if (turntableFormat_ != 0) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70.0f);
    ImGui::InputInt("fps", &turntableFps_, 0);
    turntableFps_ = std::clamp(turntableFps_, 1, 240);
  }
  ImGui::SameLine();
  const bool turntable = ImGui::Button("Turntable");
  layout_.lastItem("turntable-button");
  ImGui::SameLine();
  // A tour flies through the camera bookmarks in order, resting at each (--tour).
  const bool canTour = view.bookmarks && view.bookmarks->size() >= 2;
  ImGui::BeginDisabled(!canTour);
  const bool tour = ImGui::Button("Tour");
  ImGui::EndDisabled();
  if (canTour) layout_.lastItem("tour-button");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(canTour ? "fly through the camera bookmarks in order"
                              : "add two camera bookmarks or more for a tour");
  if (turntable || tour) {
    edits.turntableFrames = turntableFrames_;
    edits.turntableFormat = kFormats[turntableFormat_];
    edits.turntableFps = turntableFps_;
    edits.tour = tour;
  }
}

}  // namespace ewa
