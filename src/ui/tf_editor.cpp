// TfEditor: draws the opacity plot and colour bar, turns mouse input into point edits, and
// runs presets, save, load and ParaView import.
#include "ui/tf_editor.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <utility>

#include "core/transfer_function_presets.h"
#include "io/paraview_colormap.h"
#include "io/transfer_function_io.h"

namespace ewa {
namespace {

constexpr float kPlotWidth = 360.0f, kPlotHeight = 150.0f;
constexpr float kBarHeight = 18.0f, kMarkerHeight = 10.0f;
constexpr float kPickRadius = 7.0f;

ImU32 rgba(const glm::dvec3& c, float alpha = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(float(c.r), float(c.g), float(c.b), alpha));
}

}  // namespace

TfEditor::TfEditor(const Volume& volume, TransferFunction tf, std::string savePath)
    : volume_(volume), tf_(std::move(tf)), history_(tf_) {
  std::snprintf(path_, sizeof path_, "%s", savePath.c_str());
  for (uint64_t count : volume.histogram()) histogram_.push_back(float(count));
  canvas_.lo = volume.minValue();
  canvas_.hi = volume.maxValue();
}

void TfEditor::reportError(const std::string& message) {
  status_ = message;
  statusIsError_ = true;
  std::cerr << "ewaview: " << message << "\n";
}

bool TfEditor::draw() {
  bool changed = false;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - kPlotWidth - 26.0f, 10.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin("Transfer function", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    // The plot comes first so that its place depends only on the window's position.
    changed |= drawOpacityPlot();
    changed |= drawColorBar();
    ImGui::TextDisabled("click: add   drag: move   right-click: remove");
    // Undo and redo beside the histogram switch: the window keeps its height.
    ImGui::Checkbox("log histogram", &logHistogram_);
    ImGui::SameLine(0.0f, 40.0f);
    changed |= drawHistory();
    changed |= loadPendingFile();
    if (!pendingPreset_.empty()) changed |= applyPreset(std::exchange(pendingPreset_, {}));
    changed |= drawSelectedPoint();
    ImGui::Separator();
    changed |= drawPresets();
    changed |= drawFiles();
    if (changed) editedSinceFile_ = !justLoaded_;
    justLoaded_ = false;
    // An edit ends when nothing is held: a drag of many frames becomes one step.
    if (!dragging() && !ImGui::IsAnyItemActive()) history_.settle(tf_);
    if (!status_.empty()) {
      if (statusIsError_) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.35f, 1.0f));
        ImGui::TextWrapped("%s", status_.c_str());
        ImGui::PopStyleColor();
      } else {
        ImGui::TextWrapped("%s", status_.c_str());
      }
    }
  }
  ImGui::End();
  return changed;
}

bool TfEditor::drawOpacityPlot() {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  canvas_.x = origin.x;
  canvas_.y = origin.y;
  canvas_.width = kPlotWidth;
  canvas_.height = kPlotHeight;
  if (printLayout_ && (origin.x != printedX_ || origin.y != printedY_)) {
    printedX_ = origin.x;
    printedY_ = origin.y;
    std::printf("tf-canvas %.0f %.0f %.0f %.0f\n", origin.x, origin.y, kPlotWidth, kPlotHeight);
    std::fflush(stdout);
  }
  ImGui::InvisibleButton("##opacity", ImVec2(kPlotWidth, kPlotHeight),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  const bool hovered = ImGui::IsItemHovered();
  const ImVec2 mouse = ImGui::GetMousePos();
  bool changed = false;

  if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
    dragOpacity_ = canvas_.pickOpacity(tf_, mouse.x, mouse.y, kPickRadius);
    if (dragOpacity_ < 0) {  // empty space: a new point under the cursor
      dragOpacity_ = int(tf_.addOpacityPoint(canvas_.toValue(mouse.x), canvas_.toAlpha(mouse.y)));
      changed = true;
    }
    selectedOpacity_ = dragOpacity_;
    // Grabbing a point a few pixels off its centre must not make it jump to the cursor.
    const OpacityPoint& p = tf_.opacity[size_t(dragOpacity_)];
    grabOffsetX_ = canvas_.toX(p.value) - mouse.x;
    grabOffsetY_ = canvas_.toY(p.alpha) - mouse.y;
  } else if (dragOpacity_ >= 0 && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    const OpacityPoint before = tf_.opacity[size_t(dragOpacity_)];
    tf_.moveOpacityPoint(size_t(dragOpacity_), canvas_.toValue(mouse.x + grabOffsetX_),
                         canvas_.toAlpha(mouse.y + grabOffsetY_));
    changed = !(tf_.opacity[size_t(dragOpacity_)] == before);
  }
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragOpacity_ = -1;
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
    const int hit = canvas_.pickOpacity(tf_, mouse.x, mouse.y, kPickRadius);
    if (hit >= 0) {
      tf_.removeOpacityPoint(size_t(hit));
      selectedOpacity_ = dragOpacity_ = -1;
      changed = true;
    }
  }

  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 end(origin.x + kPlotWidth, origin.y + kPlotHeight);
  // Points outside the volume's range (from a loaded file) stay inside the plot's frame.
  draw->PushClipRect(ImVec2(origin.x - 6.0f, origin.y - 6.0f), ImVec2(end.x + 6.0f, end.y + 6.0f),
                     true);
  draw->AddRectFilled(origin, end, IM_COL32(22, 22, 26, 255));
  // Histogram behind the curve.
  float top = 0.0f;
  for (float c : histogram_) top = std::max(top, logHistogram_ ? std::log1p(c) : c);
  const float binWidth = kPlotWidth / float(std::max<size_t>(1, histogram_.size()));
  for (size_t b = 0; b < histogram_.size() && top > 0.0f; ++b) {
    const float h = (logHistogram_ ? std::log1p(histogram_[b]) : histogram_[b]) / top;
    const float x0 = origin.x + b * binWidth;
    draw->AddRectFilled(ImVec2(x0, end.y - h * kPlotHeight), ImVec2(x0 + binWidth, end.y),
                        IM_COL32(90, 90, 100, 255));
  }
  // The function itself: each column filled up to its opacity in its colour.
  std::vector<ImVec2> curve;
  for (int column = 0; column < int(kPlotWidth); ++column) {
    const float x = origin.x + column + 0.5f;
    const double v = canvas_.toValue(x);
    const float y = canvas_.toY(tf_.alphaAt(v));
    draw->AddLine(ImVec2(x, end.y), ImVec2(x, y), rgba(tf_.colorAt(v), 0.55f));
    curve.push_back(ImVec2(x, y));
  }
  draw->AddPolyline(curve.data(), int(curve.size()), IM_COL32(235, 235, 235, 255), 0, 1.5f);
  for (size_t i = 0; i < tf_.opacity.size(); ++i) {
    const ImVec2 p(canvas_.toX(tf_.opacity[i].value), canvas_.toY(tf_.opacity[i].alpha));
    const bool selected = int(i) == selectedOpacity_;
    draw->AddCircleFilled(p, 5.0f, rgba(tf_.colorAt(tf_.opacity[i].value)));
    draw->AddCircle(p, 5.5f, selected ? IM_COL32(255, 220, 0, 255) : IM_COL32(255, 255, 255, 255),
                    0, selected ? 2.0f : 1.0f);
  }
  draw->AddRect(origin, end, IM_COL32(120, 120, 130, 255));
  draw->PopClipRect();
  return changed;
}

bool TfEditor::drawColorBar() {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float height = kBarHeight + kMarkerHeight;
  ImGui::InvisibleButton("##colors", ImVec2(kPlotWidth, height),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  const bool hovered = ImGui::IsItemHovered();
  const ImVec2 mouse = ImGui::GetMousePos();
  bool changed = false;
  if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
    dragColor_ = canvas_.pickColor(tf_, mouse.x, kPickRadius);
    if (dragColor_ < 0) {  // a new point with the colour already there
      const double v = canvas_.toValue(mouse.x);
      dragColor_ = int(tf_.addColorPoint(v, tf_.colorAt(v)));
      changed = true;
    }
    selectedColor_ = dragColor_;
    grabOffsetX_ = canvas_.toX(tf_.color[size_t(dragColor_)].value) - mouse.x;
  } else if (dragColor_ >= 0 && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    const double before = tf_.color[size_t(dragColor_)].value;
    tf_.moveColorPoint(size_t(dragColor_), canvas_.toValue(mouse.x + grabOffsetX_));
    changed = tf_.color[size_t(dragColor_)].value != before;
  }
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragColor_ = -1;
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
    const int hit = canvas_.pickColor(tf_, mouse.x, kPickRadius);
    if (hit >= 0) {
      tf_.removeColorPoint(size_t(hit));
      selectedColor_ = dragColor_ = -1;
      changed = true;
    }
  }

  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(ImVec2(origin.x - 6.0f, origin.y),
                     ImVec2(origin.x + kPlotWidth + 6.0f, origin.y + height), true);
  for (int column = 0; column < int(kPlotWidth); ++column) {
    const float x = origin.x + column + 0.5f;
    draw->AddLine(ImVec2(x, origin.y), ImVec2(x, origin.y + kBarHeight),
                  rgba(tf_.colorAt(canvas_.toValue(x))));
  }
  for (size_t i = 0; i < tf_.color.size(); ++i) {
    const float x = canvas_.toX(tf_.color[i].value);
    const float y = origin.y + kBarHeight;
    const bool selected = int(i) == selectedColor_;
    draw->AddTriangleFilled(ImVec2(x, y), ImVec2(x - 5.0f, y + kMarkerHeight),
                            ImVec2(x + 5.0f, y + kMarkerHeight), rgba(tf_.color[i].rgb));
    draw->AddTriangle(ImVec2(x, y), ImVec2(x - 5.0f, y + kMarkerHeight),
                      ImVec2(x + 5.0f, y + kMarkerHeight),
                      selected ? IM_COL32(255, 220, 0, 255) : IM_COL32(255, 255, 255, 255), 1.0f);
  }
  draw->PopClipRect();
  return changed;
}

bool TfEditor::loadPendingFile() {
  if (pendingFile_.empty()) return false;
  const std::string path = std::move(pendingFile_);
  pendingFile_.clear();
  try {
    std::string what;
    tf_ = loadTransferFunctionOrPreset(path, tf_, volume_.minValue(), volume_.maxValue(), &what);
    selectedOpacity_ = selectedColor_ = dragOpacity_ = dragColor_ = -1;
    status_ = what;
    statusIsError_ = false;
    if (what.rfind("loaded ", 0) == 0) {  // ewaview's own file: Save writes it back there
      lastFile_ = path;
      justLoaded_ = true;
      std::snprintf(path_, sizeof path_, "%s", path.c_str());
    }
    std::cerr << "ewaview: " << what << "\n";
    return true;
  } catch (const std::exception& e) {
    reportError(e.what());
    return false;
  }
}

bool TfEditor::applyPreset(const std::string& name) {
  try {
    tf_ = applyTransferFunctionPreset(tf_, name, volume_.minValue(), volume_.maxValue());
  } catch (const std::exception& e) {  // an unknown name, or a volume of one value
    reportError(e.what());
    return false;
  }
  selectedOpacity_ = selectedColor_ = -1;
  status_ = "preset: " + name;
  statusIsError_ = false;
  return true;
}

bool TfEditor::drawHistory() {
  int step = pendingStep_;
  pendingStep_ = 0;
  ImGui::BeginDisabled(!history_.canUndo(tf_));
  if (ImGui::Button("Undo")) step = -1;
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Ctrl+Z: undo the last edit (%zu kept)", history_.undoSteps());
  ImGui::SameLine();
  ImGui::BeginDisabled(!history_.canRedo(tf_));
  if (ImGui::Button("Redo")) step = 1;
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Ctrl+Y or Ctrl+Shift+Z: redo what was undone");
  if (step == 0) return false;
  const std::optional<TransferFunction> back = step < 0 ? history_.undo(tf_) : history_.redo(tf_);
  if (!back) return false;
  tf_ = *back;
  // Indices of another function's points.
  dragOpacity_ = dragColor_ = selectedOpacity_ = selectedColor_ = -1;
  status_ = step < 0 ? "undone" : "redone";
  statusIsError_ = false;
  return true;
}

bool TfEditor::drawSelectedPoint() {
  bool changed = false;
  ImGui::PushItemWidth(120.0f);
  if (selectedOpacity_ >= 0 && selectedOpacity_ < int(tf_.opacity.size())) {
    OpacityPoint p = tf_.opacity[size_t(selectedOpacity_)];
    const double speed = canvas_.span() / 500.0;
    bool edited = ImGui::DragScalar("value##o", ImGuiDataType_Double, &p.value, float(speed));
    ImGui::SameLine();
    const double zero = 0.0, one = 1.0;
    edited |= ImGui::SliderScalar("alpha", ImGuiDataType_Double, &p.alpha, &zero, &one, "%.3f");
    if (edited) {
      tf_.moveOpacityPoint(size_t(selectedOpacity_), p.value, p.alpha);
      changed = true;
    }
  }
  if (selectedColor_ >= 0 && selectedColor_ < int(tf_.color.size())) {
    const ColorPoint& p = tf_.color[size_t(selectedColor_)];
    float c[3] = {float(p.rgb.r), float(p.rgb.g), float(p.rgb.b)};
    ImGui::Text("colour point at %g", p.value);
    ImGui::SameLine();
    if (ImGui::ColorEdit3("##pointcolour", c)) {
      tf_.setPointColor(size_t(selectedColor_), glm::dvec3(c[0], c[1], c[2]));
      changed = true;
    }
  }
  ImGui::PopItemWidth();
  return changed;
}

bool TfEditor::drawPresets() {
  bool changed = false;
  ImGui::PushItemWidth(200.0f);
  if (ImGui::BeginCombo("preset", "choose...")) {
    for (const TransferFunctionPresetInfo& p : transferFunctionPresets()) {
      if (ImGui::Selectable(p.name.c_str())) changed |= applyPreset(p.name);
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button("From histogram")) {
    tf_ = defaultTransferFunction(volume_);
    selectedOpacity_ = selectedColor_ = -1;
    changed = true;
  }
  ImGui::PopItemWidth();
  return changed;
}

bool TfEditor::drawFiles() {
  bool changed = false;
  ImGui::PushItemWidth(kPlotWidth - 40.0f);
  ImGui::InputText("file", path_, sizeof path_);
  ImGui::PopItemWidth();
  const std::string path = path_;
  if (ImGui::Button("Save")) {
    try {
      saveTransferFunction(path, tf_);
      status_ = "saved " + path;
      statusIsError_ = false;
      lastFile_ = path;
      editedSinceFile_ = false;
    } catch (const std::exception& e) {
      reportError(e.what());
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Load")) {
    try {
      tf_ = loadTransferFunction(path);
      selectedOpacity_ = selectedColor_ = -1;
      status_ = "loaded " + path;
      statusIsError_ = false;
      lastFile_ = path;
      justLoaded_ = true;
      changed = true;
    } catch (const std::exception& e) {
      reportError(e.what());
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Import ParaView")) {
    try {
      imported_ = loadParaViewPresets(path);
      importedIndex_ = 0;
      tf_ = applyImportedColorMap(tf_, imported_[0], volume_.minValue(), volume_.maxValue(),
                                  rescaleImport_);
      selectedOpacity_ = selectedColor_ = -1;
      status_ = "imported \"" + imported_[0].name + "\" (" + std::to_string(imported_.size()) +
                " in the file)";
      statusIsError_ = false;
      changed = true;
    } catch (const std::exception& e) {
      reportError(e.what());
    }
  }
  ImGui::SameLine();
  ImGui::Checkbox("rescale", &rescaleImport_);
  if (imported_.size() > 1) {
    ImGui::PushItemWidth(200.0f);
    if (ImGui::BeginCombo("imported", imported_[size_t(importedIndex_)].name.c_str())) {
      for (size_t i = 0; i < imported_.size(); ++i) {
        if (ImGui::Selectable(imported_[i].name.c_str(), int(i) == importedIndex_)) {
          importedIndex_ = int(i);
          tf_ = applyImportedColorMap(tf_, imported_[i], volume_.minValue(), volume_.maxValue(),
                                      rescaleImport_);
          changed = true;
        }
      }
      ImGui::EndCombo();
    }
    ImGui::PopItemWidth();
  }
  return changed;
}

}  // namespace ewa
