// The view on screen as command-line options (the window's "Copy view"), so a script renders
// the same picture headless: ewaview FILE $(options) -o view.png.
#pragma once

#include <glm/vec2.hpp>
#include <string>

#include "core/camera.h"
#include "core/clip_region.h"

namespace ewa {

// "--camera-position=X,Y,Z --camera-focal-point=... --camera-view-up=... --camera-view-angle=A"
// (and --camera-orthographic), then --resolution=W,H, then --crop and each enabled
// --clip-plane of `clip`. Every option is one word with '=' (a leading minus is never taken
// for an option) and numbers in enough digits to read back within 1e-9 of the value.
std::string viewOptionsText(const Camera& camera, glm::ivec2 size, const ClipRegion& clip);

}  // namespace ewa
