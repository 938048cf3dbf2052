// The crop box and clipping planes as JSON, for the window's settings and camera bookmarks.
#pragma once

#include <nlohmann/json.hpp>

#include "core/clip_region.h"

namespace ewa {

// {"crop": {"enabled": true, "min": [x, y, z], "max": [x, y, z]},
//  "planes": [{"point": [x, y, z], "normal": [x, y, z], "enabled": true}, ...]}
nlohmann::json clipRegionToJson(const ClipRegion& region);
// Missing keys keep the defaults (nothing clipped). Throws std::runtime_error("clip: problem")
// for values of the wrong type, non-finite numbers, an inverted box, a zero normal or more
// than ClipRegion::kMaxPlanes planes.
ClipRegion clipRegionFromJson(const nlohmann::json& j);

}  // namespace ewa
