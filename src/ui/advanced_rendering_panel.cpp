// The panel's "Advanced rendering" section: what a renderer developer turns, collapsed at start.
#include "ui/advanced_rendering_panel.h"

#include <imgui.h>

#include <cmath>

#include "core/kernel_lattice.h"
#include "ui/render_options_panel.h"

namespace ewa {

namespace {

// The combo's order, best filter first.
constexpr FilterMode kFilters[] = {FilterMode::Ewa, FilterMode::Swan, FilterMode::Plain};

// A slider over a double (the settings are doubles; ImGui's float sliders would round them).
bool sliderDouble(const char* label, double* value, double lo, double hi, const char* format,
                  ImGuiSliderFlags flags = 0) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, value, &lo, &hi, format,
                             flags | ImGuiSliderFlags_AlwaysClamp);
}

bool drawShearWarp(ShearWarpSettings& s) {
  bool changed = ImGui::Checkbox("pre-integrated", &s.preintegrated);
  if (s.preintegrated) {
    bool bilinear = s.lookup == TableLookup::Bilinear;
    if (ImGui::Checkbox("bilinear table lookup", &bilinear)) {
      s.lookup = bilinear ? TableLookup::Bilinear : TableLookup::Nearest;
      changed = true;
    }
    bool image = s.buffers == BufferSlices::Image;
    if (ImGui::Checkbox("image-sized buffer slice", &image)) {
      s.buffers = image ? BufferSlices::Image : BufferSlices::Slice;
      changed = true;
    }
  }
  changed |= ImGui::Checkbox("opacity correction", &s.opacityCorrection);
  // Finer than the picture gains nothing; 1 is the paper's (close-ups magnified by the warp).
  changed |= sliderDouble("intermediate px/voxel", &s.intermediateScale, 1.0, 4.0, "%.2f");
  return changed;
}

// The splat renderer's filter, kernel and classification knobs.
bool drawSplatKnobs(RenderSettings& settings, LayoutLog& layout) {
  bool changed = false;
  int filter = 0;
  for (int i = 0; i < 3; ++i)
    if (kFilters[i] == settings.filter) filter = i;
  if (ImGui::BeginCombo("filter", filterModeName(kFilters[filter]))) {
    for (int i = 0; i < 3; ++i) {
      if (ImGui::Selectable(filterModeName(kFilters[i]), i == filter) && i != filter) {
        settings.filter = kFilters[i];
        changed = true;
      }
    }
    ImGui::EndCombo();
  }

  changed |= sliderDouble("cutoff", &settings.cutoff, 1.0, 16.0, "%.2f");
  layout.lastItem("knob-cutoff");
  // The kernels' depth profile: cut at sqrt(depth cutoff) sigma (fewer slabs a kernel), or not.
  bool cut = std::isfinite(settings.depthCutoff);
  if (ImGui::Checkbox("cut depth profile", &cut)) {
    settings.depthCutoff = cut ? RenderSettings().depthCutoff : INFINITY;
    changed = true;
  }
  if (cut) {
    changed |= sliderDouble("depth cutoff", &settings.depthCutoff, 0.25, 16.0, "%.2f");
    layout.lastItem("knob-depth-cutoff");
  }
  changed |=
      sliderDouble("kernel width", &settings.kernelWidth, kMinKernelWidth, kMaxKernelWidth, "%.2f");
  layout.lastItem("knob-kernel-width");
  // Post-classification splats values and classifies per pixel: no surface splats there.
  bool post = settings.classification.mode == ClassificationMode::Post;
  if (ImGui::Checkbox("post-classified", &post)) {
    settings.classification.mode = post ? ClassificationMode::Post : ClassificationMode::Pre;
    if (post) settings.classification.surface = SurfaceCriterion::None;
    changed = true;
  }
  ImGui::BeginDisabled(!post);
  ImGui::SameLine();
  changed |= ImGui::Checkbox("pre-integrated", &settings.slabPreintegration);
  ImGui::EndDisabled();
  // Depth samples a slab: its quarters (nearer a ray caster close up) or its halves (cheaper).
  ImGui::BeginDisabled(!post || !settings.slabPreintegration);
  bool quarters = settings.slabSamples >= 4;
  if (ImGui::Checkbox("4 samples a slab", &quarters)) {
    settings.slabSamples = quarters ? 4 : 2;
    changed = true;
  }
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "Post-classified, pre-integrated: each slab's value at 4 depths (its quarters) or 2 "
        "(its halves: cheaper, softer in depth; ewaview --slab-samples)");
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("close-up")) {
    applyCloseUpSettings(&settings);
    changed = true;
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Post-classified, pre-integrated, kernel width 0.7, cutoff 5, prefilter 0.04: nearest "
        "to a ray caster close up (ewaview --close-up)");
  int precision = int(settings.slabPrecision);
  const char* precisions[] = {"auto", "half", "float"};
  ImGui::SetNextItemWidth(90.0f);
  if (ImGui::Combo("slab floats", &precision, precisions, 3)) {
    settings.slabPrecision = SlabPrecision(precision);
    changed = true;
  }
  layout.lastItem("knob-slab-floats");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Slab images of half floats (about twice as fast on a GPU, within a few levels) or "
        "floats; auto: half for kernel widths up to 1 unless shaded and post-classified "
        "(ewaview --slab-precision)");
  ImGui::BeginDisabled(!post);
  changed |=
      sliderDouble("prefilter", &settings.classification.prefilter, 0.0, kMaxPrefilter, "%.3f");
  layout.lastItem("knob-prefilter");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "Post-classified: each splat's value sharpened by this times its discrete Laplacian, "
        "nearer interpolating the voxels (0: the data's values; ewaview --prefilter)");
  // Shaded post-classification's normals: the data's gradient along each ray, the field's
  // (pre-integrated only) or the voxels'. In PostNormals' order.
  int normals = int(settings.postNormals);
  const char* normalNames[] = {"field", "voxel", "ray"};
  ImGui::SetNextItemWidth(90.0f);
  if (ImGui::Combo("normals", &normals, normalNames, 3)) {
    settings.postNormals = PostNormals(normals);
    changed = true;
  }
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "Shaded, post-classified: normals from the data's gradient along each pixel's ray (ray, "
        "as a ray caster shades), the gradient of the reconstructed field (field; "
        "pre-integrated only) or the voxels' normals (voxel); ewaview --post-normals");
  ImGui::EndDisabled();
  changed |= sliderDouble("slab (voxels)", &settings.slabThickness, 0.25, 8.0, "%.2f",
                          ImGuiSliderFlags_Logarithmic);
  layout.lastItem("knob-slab-thickness");
  changed |= ImGui::Checkbox("coarse slabs", &settings.coarseSlabs);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Slabs whose kernels are all at least 2.5 pixels wide are splatted into images 1.25 "
        "to 4 times coarser (each kernel 2 texels wide) and read back bilinearly: faster close "
        "up, within a few levels (ewaview --slab-resolution auto; off: full)");
  return changed;
}

}  // namespace

bool drawAdvancedRendering(RenderSettings& settings, double valueMin, double valueMax,
                           bool& levelOfDetail, bool* levelOfDetailChanged, LayoutLog& layout) {
  *levelOfDetailChanged = false;
  const bool open = ImGui::CollapsingHeader("Advanced rendering");
  layout.lastItem("section-advanced");
  if (!open) return false;
  bool changed = false;
  ImGui::PushItemWidth(180.0f);
  int kind = int(settings.renderer);
  const char* kinds[] = {"EWA splatting (GPU)", "shear-warp (CPU)"};
  if (ImGui::Combo("renderer", &kind, kinds, 2) && kind != int(settings.renderer)) {
    settings.renderer = RendererKind(kind);
    changed = true;
  }
  const bool shearWarp = settings.renderer == RendererKind::ShearWarp;
  if (shearWarp) changed |= drawShearWarp(settings.shearWarp);
  ImGui::BeginDisabled(shearWarp);  // the splat renderer's own settings
  changed |= drawSplatKnobs(settings, layout);
  ImGui::EndDisabled();
  *levelOfDetailChanged = ImGui::Checkbox("coarser while moving", &levelOfDetail);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Coarser levels of detail while the view moves, refined once it holds still");
  changed |= drawCompositingOptions(settings, valueMin, valueMax);
  ImGui::PopItemWidth();
  return changed;
}

}  // namespace ewa
