// Headless rendering: one picture of a scene to a PNG, through OSMesa or EGL.
#pragma once

#include <string>
#include <vector>

#include "app/options.h"
#include "app/scene.h"

namespace ewa {

// Renders the scene as the options say and writes options.output. Throws on failure.
void renderHeadless(const Scene& scene, const Options& options);

// Every file the scene was read from: the volumes' own (Volume::sourceFiles: a header's data
// files, a series' slices), the file named, the transfer function and the bookmarks.
std::vector<std::string> sceneInputFiles(const Scene& scene, const Options& options);

// Throws std::runtime_error("output: is an input file; ...") when `output` is one of
// sceneInputFiles.
void refuseToOverwriteInputs(const std::string& output, const Scene& scene, const Options& options);

}  // namespace ewa
