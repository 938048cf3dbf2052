// runViewer: the interactive window that shows a volume with the splat or shear-warp renderer.
#pragma once

#include <string>

#include "core/camera.h"
#include "io/viewer_settings.h"
#include "render/renderer.h"
#include "ui/volume_loading.h"

namespace ewa {

struct ViewerConfig {
  int width = 1024, height = 768;  // window size
  Camera camera;                   // initial camera (already framed by the caller)
  RenderSettings settings;         // renderer, filter, cutoff, slab thickness, background...
  std::string title = "ewaview";
  std::string shaderDir;  // empty: embedded shaders
  // Per-user settings folder (settings.json, imgui.ini, bookmarks of read-only volumes);
  // empty: nothing is saved. `saved` holds what was read from it (recent files...).
  std::string configDir;
  ViewerSettings saved;
  VolumeOpener opener;           // opens files from the dialog, drops and recent files
  std::string recordCameraPath;  // non-empty: every camera drawn is written here on exit
  bool watch = false;            // reload the volume whenever its file changes (--watch)
};

// Opens a window, renders `initial` with settings.renderer (switchable in the panel) and runs
// until the window closes (Escape, Q or the close button). Mouse: left-drag orbits, right-drag
// or the wheel zooms, middle-drag or shift+left-drag pans; R resets the camera, 1-6 look along
// +X -X +Y -Y +Z -Z, F12 saves a screenshot, Ctrl+O opens a file. While the view moves a
// coarser level of detail is drawn; once input stops full quality is refined in steps over UI
// frames (any input interrupts it). Settings are saved to config.configDir on exit.
// Returns the process exit code: 0, or 1 with a one-line message on stderr when no window with
// an OpenGL 4.5 core context can be made. Other failures (shader builds) throw.
int runViewer(LoadedVolume initial, const ViewerConfig& config);

}  // namespace ewa
