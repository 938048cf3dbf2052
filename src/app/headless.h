// Headless rendering: one picture of a scene to a PNG, through OSMesa or EGL.
#pragma once

#include "app/options.h"
#include "app/scene.h"

namespace ewa {

// Renders the scene as the options say and writes options.output. Throws on failure.
void renderHeadless(const Scene& scene, const Options& options);

}  // namespace ewa
