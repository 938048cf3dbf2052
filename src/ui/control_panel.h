// ControlPanel: the ImGui window that shows the volume and statistics and edits the view.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/camera_views.h"
#include "core/volume.h"
#include "gl/gpu_memory.h"
#include "render/renderer.h"
#include "ui/layout_log.h"
#include "ui/progressive_refinement.h"

namespace ewa {

// What the panel shows about the last frames.
struct FrameStats {
  RenderStats render;    // of the last render() call
  double frameMs = 0.0;  // the last window frame: events, render (if any), drawing, swap
  int imageWidth = 0;    // size of the rendered image
  int imageHeight = 0;
  int lodLevel = 0;     // LodPolicy level of the image shown (0: full quality)
  size_t gpuBytes = 0;  // buffers and images the renderers hold
  std::optional<gl::GpuMemoryInfo> gpuMemory;  // driver figures, when it reports them
  double refineProgress = -1.0;         // the full-quality frame being refined (0..1); < 0: none
  RefinementReport refinement;          // the last finished refinement
  std::vector<std::string> extraLines;  // ViewerConfig::statisticsLines of the last picture
};

// A thin progress bar along the window's bottom edge, with "refining NN%", while the
// full-quality frame is refined over the coarse picture.
void drawRefinementOverlay(double progress);

// What the user changed this frame.
struct PanelEdits {
  bool settings = false;                // the RenderSettings were edited
  bool camera = false;                  // the Camera was edited (projection, view angle)
  bool resetCamera = false;             // "Reset camera" was pressed
  bool copyView = false;                // "Copy view": the view as command-line options
  bool keysHelp = false;                // "keys (F1)": the keys window shown or hidden
  std::optional<AxisView> axisView;     // a view along an axis was asked for
  bool levelOfDetail = false;           // the level-of-detail checkbox changed
  bool axes = false;                    // the orientation axes checkbox changed
  int frameStep = 0;                    // -1 or +1: the file's previous or next volume
  int channelStep = 0;                  // -1 or +1: its previous or next channel
  std::optional<std::string> series;    // another series of the folder was chosen: its id
  std::optional<glm::dvec3> spacing;    // the file to be opened again with this voxel spacing
  std::optional<std::string> tfPreset;  // a transfer-function preset was chosen: its name
};

// Sections other objects draw into the panel's window, each called at its place in the panel
// (what a person exploring a volume changes first, the renderer's own knobs last); any may be
// empty.
struct PanelSections {
  std::function<void()> status;    // loading progress, busy work, messages (at the end)
  std::function<void()> files;     // "File": open, save, reload, recent files
  std::function<void()> clip;      // under the "Crop and clip" header, while it is open
  std::function<void()> captures;  // "Camera bookmarks", "Capture": screenshot, turntable, tour
};

class ControlPanel {
 public:
  // `volumeName` is shown as given; the volume's dims, type and spacing are copied to text now.
  ControlPanel(std::string volumeName, const Volume& volume);

  // Builds the panel between ImGuiLayer::beginFrame and render, editing `settings` and
  // `camera` in place: the volume, its file, the view (render mode, colours, camera), crop and
  // clip, bookmarks and capture, then the collapsed "Advanced rendering", the statistics and
  // the messages.
  // `levelOfDetail` is the "coarser while moving" switch, `axes` the orientation axes'.
  PanelEdits draw(RenderSettings& settings, Camera& camera, bool& levelOfDetail, bool& axes,
                  const FrameStats& stats, const PanelSections& sections = {});
  // A new volume was opened; `fromFile`: it has a file to open again with another spacing.
  void setVolume(std::string volumeName, const Volume& volume, bool fromFile = false);
  // EWAVIEW_PRINT_LAYOUT: the series list's place and its entries', the sections' headers
  // ("section-view X Y W H", ...) and the advanced knobs' ("knob-cutoff ...", drawn only while
  // their section is open) on stdout, for the window tests, each once while it stays put.
  void setPrintLayout(bool on) { layout_.setOn(on); }

 private:
  void drawVolume(PanelEdits& edits);
  void drawView(RenderSettings& settings, Camera& camera, bool& axes, PanelEdits& edits);
  bool drawCamera(Camera& camera);
  std::optional<std::string> drawColourPresets();
  std::optional<AxisView> drawAxisViews();
  std::optional<std::string> drawSeries();
  std::optional<glm::dvec3> drawSpacing();
  void drawStats(const FrameStats& stats);

  std::string volumeName_;
  std::string volumeText_;                            // "64 x 64 x 64 uint8, spacing 1 1 1"
  int frame_ = 0, frameCount_ = 1;                    // which of the file's volumes
  int channel_ = 0, channelCount_ = 1;                // which of its channels
  std::vector<SeriesChoice> series_;                  // the folder's series (DICOM), to choose from
  glm::dvec3 spacing_{1.0};                           // the volume's
  std::array<double, 3> spacingEdit_{1.0, 1.0, 1.0};  // as typed in the panel
  bool fromFile_ = false;
  LayoutLog layout_;
  std::array<double, 2> valueRange_{0.0, 1.0};
  bool patientFrame_ = false;  // label the axis views anatomically (LPS)
};

}  // namespace ewa
