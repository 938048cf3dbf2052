// runViewer: the interactive window that shows a volume with the splat or shear-warp renderer.
#pragma once

#include <string>

#include "core/camera.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "render/renderer.h"

namespace ewa {

struct ViewerConfig {
  int width = 1024, height = 768;  // window size
  Camera camera;                   // initial camera (already framed by the caller)
  RenderSettings settings;         // renderer, filter, cutoff, slab thickness, background...
  std::string title = "ewaview";
  std::string shaderDir;           // empty: embedded shaders
  std::string volumeName;          // shown in the panel
};

// Opens a window, renders `volume` with settings.renderer (switchable in the panel) and runs until the window closes
// (Escape, Q or the close button). Mouse: left-drag orbits, right-drag or the wheel zooms,
// middle-drag or shift+left-drag pans; R resets the camera. The volume is rendered again only
// when the camera, the settings or the window size change.
// Returns the process exit code: 0, or 1 with a one-line message on stderr when no window with
// an OpenGL 4.5 core context can be made. Other failures (shader builds) throw.
int runViewer(const Volume& volume, const TransferFunction& tf, const ViewerConfig& config);

}  // namespace ewa
