// Headless rendering: one picture of a scene to a PNG, through OSMesa or EGL.
#pragma once

#include <string>

#include "app/options.h"
#include "app/scene.h"

namespace ewa {

// Renders the scene as the options say and writes options.output. Throws on failure.
void renderHeadless(const Scene& scene, const Options& options);

// Throws std::runtime_error("output: is an input file; ...") when `output` is the volume or
// transfer-function file the options read.
void refuseToOverwriteInputs(const std::string& output, const Options& options);

}  // namespace ewa
