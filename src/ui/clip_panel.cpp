// The panel's "Crop and clip" section: crop box numbers, planes from the view, offsets, on/off.
#include "ui/clip_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <glm/geometric.hpp>

namespace ewa {

ClipPlane planeFacingCamera(const Camera& camera) {
  // The kept half is the one the camera looks into: the normal points away from the eye.
  return ClipPlane{camera.focalPoint, camera.direction(), true};
}

double planeOffset(const ClipPlane& plane, const glm::dvec3& centre) {
  const double len = glm::length(plane.normal);
  return len > 0.0 ? glm::dot(plane.point - centre, plane.normal) / len : 0.0;
}

void setPlaneOffset(ClipPlane& plane, const glm::dvec3& centre, double offset) {
  const double len = glm::length(plane.normal);
  if (!(len > 0.0)) return;
  const glm::dvec3 n = plane.normal / len;
  plane.point += (offset - glm::dot(plane.point - centre, n)) * n;
}

ClipPanelEdits drawClipControls(ClipRegion& region, const glm::dvec3& lo, const glm::dvec3& hi,
                                const Camera& camera) {
  ClipPanelEdits edits;
  const auto note = [&edits](bool changed) {
    edits.changed |= changed;
    edits.dragging |= ImGui::IsItemActive();
  };
  const glm::dvec3 size = hi - lo, centre = 0.5 * (lo + hi);
  ImGui::PushItemWidth(220.0f);
  bool crop = region.cropEnabled;
  if (ImGui::Checkbox("crop box", &crop)) {
    // Switched on for the first time (or after a new volume): start from the whole volume.
    if (crop && !(region.cropMin.x < region.cropMax.x && region.cropMin.y < region.cropMax.y &&
                  region.cropMin.z < region.cropMax.z)) {
      region.cropMin = lo;
      region.cropMax = hi;
    }
    region.cropEnabled = crop;
    edits.changed = true;
  }
  if (region.cropEnabled) {
    const char* axes[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
      double range[2] = {region.cropMin[a], region.cropMax[a]};
      const double speed = std::max(size[a], 1e-9) / 400.0;
      const double margin = 0.25 * size[a];
      const double min = lo[a] - margin, max = hi[a] + margin;
      char label[32];
      std::snprintf(label, sizeof label, "%s min, max", axes[a]);
      if (ImGui::DragScalarN(label, ImGuiDataType_Double, range, 2, float(speed), &min, &max,
                             "%.2f", ImGuiSliderFlags_AlwaysClamp)) {
        // Keep the box at least a hundredth of the volume thick.
        const double gap = std::max(size[a], 1e-9) * 0.01;
        if (range[1] < range[0] + gap) {
          if (range[0] != region.cropMin[a])
            range[0] = range[1] - gap;
          else
            range[1] = range[0] + gap;
        }
        region.cropMin[a] = range[0];
        region.cropMax[a] = range[1];
        edits.changed = true;
      }
      edits.dragging |= ImGui::IsItemActive();
    }
    if (ImGui::SmallButton("whole volume")) {
      region.cropMin = lo;
      region.cropMax = hi;
      edits.changed = true;
    }
  }
  ImGui::Separator();
  const double reach = 0.5 * glm::length(size);
  int remove = -1;
  for (size_t i = 0; i < region.planes.size(); ++i) {
    ClipPlane& plane = region.planes[i];
    ImGui::PushID(int(i));
    note(ImGui::Checkbox("##on", &plane.enabled));
    ImGui::SameLine();
    double offset = planeOffset(plane, centre);
    const double min = -reach, max = reach;
    char label[32];
    std::snprintf(label, sizeof label, "plane %zu", i + 1);
    if (ImGui::SliderScalar(label, ImGuiDataType_Double, &offset, &min, &max, "%.2f")) {
      setPlaneOffset(plane, centre, offset);
      edits.changed = true;
    }
    edits.dragging |= ImGui::IsItemActive();
    if (ImGui::IsItemHovered()) {
      // The wheel over the slider moves the plane too, a 200th of the volume per notch.
      const float wheel = ImGui::GetIO().MouseWheel;
      if (wheel != 0.0f) {
        setPlaneOffset(plane, centre, std::clamp(offset + wheel * 2.0 * reach / 200.0, min, max));
        edits.changed = true;
      }
      ImGui::SetTooltip("normal %.2f %.2f %.2f (kept side)", plane.normal.x, plane.normal.y,
                        plane.normal.z);
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("flip")) {
      plane.normal = -plane.normal;
      edits.changed = true;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) remove = int(i);
    ImGui::PopID();
  }
  if (remove >= 0) {
    region.planes.erase(region.planes.begin() + remove);
    edits.changed = true;
  }
  if (region.planes.size() < ClipRegion::kMaxPlanes) {
    if (ImGui::Button("Add plane from view")) {
      region.planes.push_back(planeFacingCamera(camera));
      edits.changed = true;
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Through the focal point, facing the camera: the near half is cut away");
  }
  ImGui::PopItemWidth();
  return edits;
}

}  // namespace ewa
