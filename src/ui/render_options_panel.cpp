// The panel's render-mode row and the advanced section's compositing, shading and surfaces.
#include "ui/render_options_panel.h"

#include <imgui.h>

namespace ewa {

namespace {

constexpr RenderMode kModes[] = {RenderMode::Composite, RenderMode::XRay, RenderMode::Mip};

bool slider(const char* label, double* value, double lo, double hi, const char* format) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, value, &lo, &hi, format,
                             ImGuiSliderFlags_AlwaysClamp);
}

}  // namespace

bool drawRenderMode(RenderSettings& s) {
  bool changed = false;
  for (RenderMode mode : kModes) {
    if (mode != kModes[0]) ImGui::SameLine();
    if (ImGui::RadioButton(renderModeName(mode), s.mode == mode) && s.mode != mode) {
      s.mode = mode;
      changed = true;
    }
  }
  if (s.mode == RenderMode::XRay) {
    int map = int(s.xrayMap);
    changed |= ImGui::RadioButton("exp(-sum)", &map, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("sum", &map, 1);
    s.xrayMap = XRayMap(map);
    changed |= slider("x-ray scale", &s.xrayScale, 0.01, 100.0, "%.3g");
  }
  return changed;
}

bool drawCompositingOptions(RenderSettings& s, double valueMin, double valueMax) {
  if (!ImGui::TreeNode("compositing, shading, surfaces")) return false;
  bool changed = false;
  bool backToFront = s.order == CompositeOrder::BackToFront;
  if (ImGui::Checkbox("back to front", &backToFront)) {
    s.order = backToFront ? CompositeOrder::BackToFront : CompositeOrder::FrontToBack;
    changed = true;
  }
  changed |= slider("termination", &s.terminationOpacity, 0.9, 1.0, "%.3f");
  ImGui::BeginDisabled(!s.lighting.enabled);  // "shading" in the view section switches them
  changed |= slider("ambient", &s.lighting.ambient, 0.0, 1.0, "%.2f");
  changed |= slider("diffuse", &s.lighting.diffuse, 0.0, 1.0, "%.2f");
  changed |= slider("specular", &s.lighting.specular, 0.0, 1.0, "%.2f");
  changed |= slider("shininess", &s.lighting.shininess, 1.0, 128.0, "%.0f");
  bool smooth = s.classification.gradient == GradientMode::Smooth;
  if (ImGui::Checkbox("smooth gradients", &smooth)) {
    s.classification.gradient = smooth ? GradientMode::Smooth : GradientMode::Central;
    changed = true;
  }
  ImGui::EndDisabled();
  bool surfaces = s.classification.surface == SurfaceCriterion::Value;
  ImGui::BeginDisabled(s.classification.mode == ClassificationMode::Post);
  const bool toggled = ImGui::Checkbox("surface splats at value", &surfaces);
  ImGui::EndDisabled();
  if (toggled) {
    s.classification.surface = surfaces ? SurfaceCriterion::Value : SurfaceCriterion::None;
    if (surfaces &&
        !(s.classification.threshold >= valueMin && s.classification.threshold <= valueMax))
      s.classification.threshold = 0.5 * (valueMin + valueMax);
    changed = true;
  }
  if (surfaces) {
    changed |= slider("iso value", &s.classification.threshold, valueMin, valueMax, "%.4g");
    changed |= slider("surface opacity", &s.surfaceOpacity, 0.0, 0.999, "%.3f");
  }
  ImGui::TreePop();
  return changed;
}

}  // namespace ewa
