// ControlPanel: the ImGui window that shows the volume and statistics and edits the view.
#include "ui/control_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/transfer_function_presets.h"
#include "ui/advanced_rendering_panel.h"
#include "ui/render_options_panel.h"

namespace ewa {

namespace {

// A slider over a double (the settings are doubles; ImGui's float sliders would round them).
bool sliderDouble(const char* label, double* value, double lo, double hi, const char* format,
                  ImGuiSliderFlags flags = 0) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, value, &lo, &hi, format,
                             flags | ImGuiSliderFlags_AlwaysClamp);
}

}  // namespace

ControlPanel::ControlPanel(std::string volumeName, const Volume& volume) {
  setVolume(std::move(volumeName), volume);
}

void ControlPanel::setVolume(std::string volumeName, const Volume& volume, bool fromFile) {
  volumeName_ = std::move(volumeName);
  char text[256];
  const auto& d = volume.dims();
  const glm::dvec3& s = volume.spacing();
  std::snprintf(text, sizeof text, "%lld x %lld x %lld %s, spacing %g %g %g",
                static_cast<long long>(d[0]), static_cast<long long>(d[1]),
                static_cast<long long>(d[2]), scalarName(volume.type()), s.x, s.y, s.z);
  volumeText_ = text;
  valueRange_ = {volume.minValue(), volume.maxValue()};
  patientFrame_ = volume.patientFrame();
  frame_ = volume.frame();
  frameCount_ = volume.frameCount();
  channel_ = volume.channel();
  channelCount_ = volume.channelCount();
  series_ = volume.seriesChoices();
  spacing_ = volume.spacing();
  spacingEdit_ = {spacing_.x, spacing_.y, spacing_.z};
  fromFile_ = fromFile;
  layout_.forget();
  if (volumeName_.empty()) volumeName_ = "(unnamed volume)";
}

// The voxel spacing, to type in (image slices have none; some files a wrong one): "Set"
// opens the file again with it, as --spacing does.
std::optional<glm::dvec3> ControlPanel::drawSpacing() {
  ImGui::SetNextItemWidth(220.0f);
  ImGui::InputScalarN("##spacing", ImGuiDataType_Double, spacingEdit_.data(), 3, nullptr, nullptr,
                      "%g");
  const glm::dvec3 asked(spacingEdit_[0], spacingEdit_[1], spacingEdit_[2]);
  bool valid = true;
  for (int a = 0; a < 3; ++a) valid = valid && asked[a] > 0.0 && asked[a] < 1e300;
  ImGui::SameLine();
  ImGui::BeginDisabled(!valid || asked == spacing_);
  const bool set = ImGui::Button("Set spacing");
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(valid ? "Open the file again with this voxel spacing (as --spacing does)"
                            : "Each spacing must be a positive number");
  if (!set) return std::nullopt;
  return asked;
}

PanelEdits ControlPanel::draw(RenderSettings& settings, Camera& camera, bool& levelOfDetail,
                              bool& axes, const FrameStats& stats, const PanelSections& sections) {
  PanelEdits edits;
  const auto call = [](const std::function<void()>& section) {
    if (section) section();
  };
  ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  const bool visible = ImGui::Begin("ewaview", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  layout_.window("panel");
  if (visible) {
    drawVolume(edits);
    call(sections.files);
    drawView(settings, camera, axes, edits);
    const bool clipOpen = ImGui::CollapsingHeader("Crop and clip");
    layout_.lastItem("section-clip");
    if (clipOpen) {
      ImGui::PushID("clip");  // its planes' buttons beside the bookmarks' ("x")
      call(sections.clip);
      ImGui::PopID();
    }
    call(sections.captures);
    bool lodChanged = false;
    edits.settings |= drawAdvancedRendering(settings, valueRange_[0], valueRange_[1], levelOfDetail,
                                            &lodChanged, layout_);
    edits.levelOfDetail = lodChanged;
    const bool statsOpen = ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen);
    layout_.lastItem("section-stats");
    if (statsOpen) drawStats(stats);
    ImGui::Separator();
    // Short, so that the panel stays narrow and leaves the picture room; F1 lists the rest.
    ImGui::TextDisabled("left: orbit  right/wheel: zoom  middle: pan");
    ImGui::TextDisabled("double-click: centre  M: mark");
    ImGui::SameLine();
    edits.keysHelp = ImGui::SmallButton("keys (F1)");
    // Last, so that a message coming or going moves no control above it.
    call(sections.status);
  }
  ImGui::End();
  return edits;
}

// The volume's name and size, and its file's other frames, channels and series.
void ControlPanel::drawVolume(PanelEdits& edits) {
  ImGui::TextUnformatted(volumeName_.c_str());
  ImGui::TextDisabled("%s", volumeText_.c_str());
  if (frameCount_ > 1) {  // a 4D file: page through its volumes
    if (ImGui::ArrowButton("##previous frame", ImGuiDir_Left)) edits.frameStep = -1;
    ImGui::SameLine();
    if (ImGui::ArrowButton("##next frame", ImGuiDir_Right)) edits.frameStep = 1;
    ImGui::SameLine();
    ImGui::Text("frame %d of %d (Page Up, Page Down)", frame_, frameCount_);
  }
  if (channelCount_ > 1) {  // RGB, a microscope's channels: one at a time
    if (ImGui::ArrowButton("##previous channel", ImGuiDir_Left)) edits.channelStep = -1;
    ImGui::SameLine();
    if (ImGui::ArrowButton("##next channel", ImGuiDir_Right)) edits.channelStep = 1;
    ImGui::SameLine();
    ImGui::Text("channel %d of %d (C, Shift+C)", channel_, channelCount_);
  }
  if (series_.size() > 1) edits.series = drawSeries();
  // Rarely wanted (image slices have none, a few files a wrong one): folded away.
  if (fromFile_ && ImGui::TreeNode("voxel spacing")) {
    edits.spacing = drawSpacing();
    ImGui::TreePop();
  }
}

// What a person looking at a volume turns first: how it is drawn and coloured, where from.
void ControlPanel::drawView(RenderSettings& settings, Camera& camera, bool& axes,
                            PanelEdits& edits) {
  const bool open = ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen);
  layout_.lastItem("section-view");
  if (!open) return;
  ImGui::PushItemWidth(180.0f);
  // Composite, X-ray and MIP are the splat renderer's; shear-warp composites only.
  ImGui::BeginDisabled(settings.renderer == RendererKind::ShearWarp);
  edits.settings |= drawRenderMode(settings);
  ImGui::EndDisabled();
  layout_.lastItem("view-mode");
  edits.tfPreset = drawColourPresets();
  edits.settings |= ImGui::Checkbox("shading", &settings.lighting.enabled);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Lit by a light at the camera (its terms: Advanced rendering)");
  ImGui::SameLine();
  edits.axes = ImGui::Checkbox("axes (X)", &axes);
  ImGui::SameLine();
  float background[3] = {float(settings.background.r), float(settings.background.g),
                         float(settings.background.b)};
  if (ImGui::ColorEdit3("background", background, ImGuiColorEditFlags_NoInputs)) {
    settings.background = glm::dvec3(background[0], background[1], background[2]);
    edits.settings = true;
  }
  edits.axisView = drawAxisViews();
  ImGui::SameLine();
  edits.copyView = ImGui::SmallButton("copy view");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Ctrl+C: the camera, picture size and crop as command-line options, to render this "
        "view headless");
  edits.resetCamera = ImGui::Button("Reset camera (R)");
  ImGui::SameLine();
  edits.camera = drawCamera(camera);
  ImGui::PopItemWidth();
}

// The transfer function's presets (the editor's menu too): a quick way to another look.
std::optional<std::string> ControlPanel::drawColourPresets() {
  std::optional<std::string> chosen;
  if (ImGui::BeginCombo("transfer function", "preset...")) {
    for (const TransferFunctionPresetInfo& p : transferFunctionPresets())
      if (ImGui::Selectable(p.name.c_str())) chosen = p.name;
    ImGui::EndCombo();
  }
  layout_.lastItem("view-colours");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("A transfer-function preset (the editor on the right edits its points)");
  return chosen;
}

bool ControlPanel::drawCamera(Camera& camera) {
  bool changed = false;
  bool perspective = !camera.orthographic;
  if (ImGui::Checkbox("perspective", &perspective)) {
    camera.orthographic = !perspective;
    changed = true;
  }
  // Orthographic views use the angle too: they show the height the perspective view shows at
  // the focal point, so the slider zooms both.
  changed |= sliderDouble("view angle", &camera.viewAngleDeg, 5.0, 120.0, "%.1f deg");
  return changed;
}

// The folder's series as a list: choosing another opens it (as --series does).
std::optional<std::string> ControlPanel::drawSeries() {
  std::optional<std::string> chosen;
  const auto open = std::find_if(series_.begin(), series_.end(), [](auto& c) { return c.open; });
  ImGui::SetNextItemWidth(320.0f);
  const bool listOpen =
      ImGui::BeginCombo("series", open == series_.end() ? "" : open->label.c_str());
  layout_.lastItem("series-list");
  if (listOpen) {
    for (size_t i = 0; i < series_.size(); ++i) {
      ImGui::PushID(int(i));  // labels may repeat
      if (ImGui::Selectable(series_[i].label.c_str(), series_[i].open) && !series_[i].open)
        chosen = series_[i].id;
      layout_.lastItem("series-entry " + std::to_string(i));
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("--series %s", series_[i].id.c_str());
      ImGui::PopID();
    }
    ImGui::EndCombo();
  }
  return chosen;
}

std::optional<AxisView> ControlPanel::drawAxisViews() {
  std::optional<AxisView> chosen;
  // Patient axes are named by the side the eye is on (R = from the patient's right).
  ImGui::TextUnformatted(patientFrame_ ? "view from" : "look along");
  for (AxisView v : kAxisViews) {
    ImGui::SameLine();
    if (ImGui::SmallButton(axisViewLabel(v, patientFrame_))) chosen = v;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", axisViewKeysHint(patientFrame_));
  }
  return chosen;
}

void drawRefinementOverlay(double progress) {
  const ImGuiViewport* view = ImGui::GetMainViewport();
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const float height = 4.0f;
  const ImVec2 lo(view->Pos.x, view->Pos.y + view->Size.y - height);
  const ImVec2 hi(view->Pos.x + view->Size.x, view->Pos.y + view->Size.y);
  draw->AddRectFilled(lo, hi, IM_COL32(40, 40, 40, 200));
  draw->AddRectFilled(lo, ImVec2(lo.x + float(progress) * view->Size.x, hi.y),
                      IM_COL32(90, 170, 255, 230));
  char text[32];
  std::snprintf(text, sizeof text, "refining %.0f%%", 100.0 * progress);
  const ImVec2 size = ImGui::CalcTextSize(text);
  const ImVec2 at(hi.x - size.x - 8.0f, lo.y - size.y - 4.0f);
  draw->AddRectFilled(ImVec2(at.x - 4.0f, at.y - 2.0f), ImVec2(hi.x - 4.0f, lo.y - 2.0f),
                      IM_COL32(0, 0, 0, 160), 3.0f);
  draw->AddText(at, IM_COL32(230, 230, 230, 255), text);
}

void ControlPanel::drawStats(const FrameStats& stats) {
  const RenderStats& r = stats.render;
  ImGui::Text("render %.1f ms   frame %.1f ms", r.renderMs, stats.frameMs);
  if (stats.refineProgress >= 0.0) {
    ImGui::ProgressBar(float(stats.refineProgress), ImVec2(180.0f, 0.0f));
    ImGui::SameLine();
    ImGui::TextUnformatted("full quality");
  } else if (stats.refinement.frames > 0 && stats.lodLevel == 0) {
    // Drawn in chunks over UI frames: render is the renderer's time summed over them.
    const RefinementReport& f = stats.refinement;
    ImGui::Text("refined in %.0f ms over %d frames (worst %.0f ms)", f.wallMs, f.frames,
                f.worstFrameMs);
  }
  // The stage times on two lines: on one, a slow frame's longer numbers made it the panel's
  // widest line, and the panel (sized to its contents) grew over the picture and back.
  if (r.classifyMs + r.partitionMs + r.splatMs + r.compositeMs > 0.0) {
    ImGui::Text("classify %.1f  partition %.1f ms", r.classifyMs, r.partitionMs);
    ImGui::Text("splat %.1f  composite %.1f ms", r.splatMs, r.compositeMs);
  }
  if (stats.lodLevel == 0)
    ImGui::Text("image %d x %d, full quality", stats.imageWidth, stats.imageHeight);
  else
    ImGui::Text("image %d x %d, coarse level %d", stats.imageWidth, stats.imageHeight,
                stats.lodLevel);
  ImGui::Text("GPU memory %.1f MiB (renderers)", double(stats.gpuBytes) / (1024.0 * 1024.0));
  for (const std::string& line : stats.extraLines) ImGui::TextUnformatted(line.c_str());
  if (stats.gpuMemory)
    ImGui::Text("GPU %.0f of %.0f MiB free", double(stats.gpuMemory->availableKiB) / 1024.0,
                double(stats.gpuMemory->totalKiB) / 1024.0);
  ImGui::Text("splats %zu / %zu", r.splatsDrawn, r.splatsTotal);
  ImGui::Text("slabs %zu (drawn %zu)   quad path %s", r.slabs, r.slabsDrawn,
              r.quadPass ? "yes" : "no");
  // --splatter auto may draw a GPU's whole frames (the coarse levels) in compute tiles, a
  // software rasterizer's on the CPU.
  ImGui::Text("splatter %s   passes a slab %d", splatterUsed(r), r.slabPasses);
  if (r.cpu)
    ImGui::Text("CPU: records %.1f  bins %.1f  tiles %.1f ms", r.cpuRecordsMs, r.cpuBinMs,
                r.cpuTilesMs);
  if (!r.note.empty()) ImGui::TextWrapped("%s", r.note.c_str());
  ImGui::Text("surface splats %zu   splat draws %zu", r.surfaceSplats, r.slabEntries);
  ImGui::Text("splat draws culled (occluded) %zu", r.entriesCulled);
}

}  // namespace ewa
