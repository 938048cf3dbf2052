// The panel section for compositing order, termination, shading, surface splats and X-ray.
#include "ui/render_options_panel.h"

#include <imgui.h>

namespace ewa {

namespace {

bool slider(const char* label, double* value, double lo, double hi, const char* format) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, value, &lo, &hi, format,
                             ImGuiSliderFlags_AlwaysClamp);
}

}  // namespace

bool drawRenderOptions(RenderSettings& s, double valueMin, double valueMax) {
  bool changed = false;
  if (s.mode == RenderMode::XRay) {
    int map = int(s.xrayMap);
    changed |= ImGui::RadioButton("exp(-sum)", &map, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("sum", &map, 1);
    s.xrayMap = XRayMap(map);
    changed |= slider("x-ray scale", &s.xrayScale, 0.01, 100.0, "%.3g");
  }
  if (!ImGui::CollapsingHeader("compositing, shading, surfaces")) return changed;
  bool backToFront = s.order == CompositeOrder::BackToFront;
  if (ImGui::Checkbox("back to front", &backToFront)) {
    s.order = backToFront ? CompositeOrder::BackToFront : CompositeOrder::FrontToBack;
    changed = true;
  }
  changed |= slider("termination", &s.terminationOpacity, 0.9, 1.0, "%.3f");
  changed |= ImGui::Checkbox("shading", &s.lighting.enabled);
  if (s.lighting.enabled) {
    changed |= slider("ambient", &s.lighting.ambient, 0.0, 1.0, "%.2f");
    changed |= slider("diffuse", &s.lighting.diffuse, 0.0, 1.0, "%.2f");
    changed |= slider("specular", &s.lighting.specular, 0.0, 1.0, "%.2f");
    changed |= slider("shininess", &s.lighting.shininess, 1.0, 128.0, "%.0f");
    bool smooth = s.classification.gradient == GradientMode::Smooth;
    if (ImGui::Checkbox("smooth gradients", &smooth)) {
      s.classification.gradient = smooth ? GradientMode::Smooth : GradientMode::Central;
      changed = true;
    }
  }
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
  return changed;
}

}  // namespace ewa
