// windowConfig: the window's settings from the command line and the saved settings, shared by
// ewaview's window and ewaview-mpi's.
#pragma once

#include <string>

#include "app/options.h"
#include "ui/viewer.h"

namespace ewa {

// The viewer's configuration for `options`: the settings folder and what it saved (window size,
// render settings, the last crop box and planes when `clipKey` names the volume it showed them
// on), each given option winning, and the shader folder, camera recording and --watch. Returns
// the options as the window applies them (size and render settings); the camera and the opener
// are the caller's.
Options windowConfig(const Options& options, const std::string& clipKey, ViewerConfig* config);

}  // namespace ewa
