// runViewer: the interactive window that shows a volume with the splat or shear-warp renderer.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/camera.h"
#include "io/viewer_settings.h"
#include "render/renderer.h"
#include "ui/volume_loading.h"

namespace ewa {

namespace platform {
class GlContext;
}

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
  // Makes every level's renderer in place of settings.renderer's, given the window's context
  // (ewaview-mpi's window: each frame drawn by every rank); null: the built-in renderers. With
  // it the moving levels only shrink the image (no coarse volumes are made: their renderers
  // would draw the same bricks) and the renderer kind stays the splat renderer.
  std::function<std::unique_ptr<Renderer>(platform::GlContext& window)> rendererFactory;
  // Non-empty: why no other file can be opened, nor this one reloaded or saved, from the window
  // (shown when asked; the volume on screen is a stand-in for one the window does not hold).
  std::string fixedVolume;
  // Lines the statistics section shows after its own (the ranks' figures of the last frame).
  std::function<std::vector<std::string>()> statisticsLines;
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
