// CursorProbe: what the picture shows under the mouse cursor (point, voxel, value), kept up to
// date as the cursor, camera or transfer function change, and drawn as a line over the picture.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <optional>
#include <string>

#include "core/volume_pick.h"

namespace ewa {

struct RenderSettings;

// What a pick depends on besides the cursor: the volume and the revisions of the camera, the
// settings (render mode, crop and clip) and the transfer function.
struct ProbeStamp {
  const Volume* volume = nullptr;
  uint64_t camera = 0, settings = 0, tf = 0;
  bool operator==(const ProbeStamp& o) const {
    return volume == o.volume && camera == o.camera && settings == o.settings && tf == o.tf;
  }
};

class CursorProbe {
 public:
  // Picks again when the cursor (window coordinates; nullopt when it is off the picture, over a
  // panel or dragging) or the stamp changed since the last pick.
  void update(const Volume& volume, const TransferFunction& tf, const RenderSettings& settings,
              const Camera& camera, glm::ivec2 windowSize, std::optional<glm::dvec2> cursor,
              const ProbeStamp& stamp);
  // The line drawn over the picture (describePick); "" when nothing is under the cursor.
  const std::string& text() const { return text_; }
  // The last pick (hit == false when nothing is under the cursor).
  const PickResult& last() const { return last_; }
  // A world point distances are measured from (the M key), or none.
  void setMark(std::optional<glm::dvec3> mark);
  const std::optional<glm::dvec3>& mark() const { return mark_; }
  // Draws text() over the picture's bottom-right corner and the mark where `camera` sees it
  // (ImGui foreground); `lifted` puts the text a line higher, above the refinement's label.
  void draw(bool lifted, const Camera& camera, glm::ivec2 windowSize) const;
  // Whether text() changed in the last update (the layout log prints it then).
  bool changed() const { return changed_; }

 private:
  bool shown_ = false;
  bool changed_ = false;
  glm::dvec2 cursor_{-1.0};
  ProbeStamp stamp_;
  PickResult last_;
  std::optional<glm::dvec3> mark_;
  std::string text_;
};

}  // namespace ewa
