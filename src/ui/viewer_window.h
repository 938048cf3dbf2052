// ViewerWindow: everything that lives as long as the viewer's window; its jobs are spread over
// viewer.cpp (the loop and drawing), viewer_files.cpp (volumes and renderers),
// viewer_capture.cpp (screenshots, turntables, recordings) and viewer_panels.cpp (panels, keys).
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "core/camera_controller.h"
#include "core/camera_tour.h"
#include "core/lod_policy.h"
#include "gl/shader_library.h"
#include "io/file_watch.h"
#include "io/frame_names.h"
#include "io/frame_sink.h"
#include "io/terminal_progress.h"
#include "platform/glfw_window_context.h"
#include "render/lod_renderer.h"
#include "ui/bookmark_store.h"
#include "ui/control_panel.h"
#include "ui/cursor_probe.h"
#include "ui/file_dialog.h"
#include "ui/image_presenter.h"
#include "ui/imgui_layer.h"
#include "ui/live_transfer_function.h"
#include "ui/progressive_refinement.h"
#include "ui/session_panel.h"
#include "ui/status_messages.h"
#include "ui/viewer.h"
#include "ui/volume_save_job.h"
#include "ui/window_input.h"

namespace ewa {

struct SplatProgramSet;

// A turntable being written from the window, one frame per loop iteration.
struct WindowTurntable {
  int total = 0;  // 0: none running
  int done = 0;
  Camera start;
  std::vector<TourStop> tour;       // a tour through these stops instead of a turn about `start`
  std::unique_ptr<FrameSink> sink;  // PNG frames in a folder, or a video
  std::unique_ptr<TerminalProgress> progress;
};

// A picture for a file, refined over UI frames like the window's own full-quality picture so
// that the window keeps answering meanwhile: a screenshot's, or a turntable's or tour's frame.
struct PendingCapture {
  bool active = false;
  bool started = false;  // its refinement has begun
  Camera camera;
  ClipRegion clip;
  glm::ivec2 size{0, 0};
  std::string path;  // a screenshot's file; empty: the turntable's next frame
  // A screenshot of the view on screen: the revisions it was asked at, so that a finished
  // picture of the window's size that still matches them stands as the window's own.
  uint64_t cameraRevision = 0, settingsRevision = 0, tfRevision = 0;
  // The transfer function its refinement began with: an edit since (its new splats come from
  // the worker) begins it again.
  uint64_t startedTfRevision = 0;
};

// Members are destroyed in reverse order, so GL objects go before the context and ImGui before
// the callbacks it chains to.
class ViewerWindow {
 public:
  ViewerWindow(platform::GlfwWindowContext& window, LoadedVolume initial,
               const ViewerConfig& config);
  void run();
  // The cameras of the moving frames, replayable by ewaview-interact-bench --path.
  void saveRecording();
  // Window size, render settings, recent files and the panel layout, for the next run.
  void saveSettings();

 private:
  using Clock = std::chrono::steady_clock;

  // viewer.cpp: the loop, rendering and refinement.
  double now() const;
  bool busy() const;
  bool refineDue() const;
  bool warmUpDue() const;
  // Asks the worker for the full level's splats of the volume on screen.
  void requestFullLevel();
  double waitSeconds() const;
  // `activity`: input or new splats this frame (a frame that only refines may skip presenting).
  bool drawFrame(bool activity);
  // With levels of detail, at a size not drawn before: makes the moving level's images there
  // (on the upload context's worker), waiting kImageWaitMs at most; false while they are not
  // all there (imagesPending_), so that the frame drawing the level does not make them.
  bool movingImagesReady(const glm::ivec2& fb);
  // Renders one level of detail now, whole; returns the milliseconds it took.
  double renderLevel(int level, const Camera& camera, const glm::ivec2& fb);
  // Records a new picture on screen (rendered or refined) for the staleness checks and panel.
  void noteImage(const glm::ivec2& fb);
  // The statistics panel's figures of the picture lod_ last finished, drawn at `level`.
  void noteFrameStats(int level);
  // Asks the worker for the full level's splats of the classification `settings` need, once,
  // where the full renderer lacks them; true when asked now (the caller waits for them).
  bool askForFullSplats(const RenderSettings& settings);
  void renderFailed(const std::exception& e, const glm::ivec2& fb);
  // The progressive full-quality frame: start it, or draw this frame's share of it (the
  // budget smaller where the frame presents: after `activity` or the present interval).
  bool refine(const glm::ivec2& fb, bool activity);
  void logFrame(double ms);

  // viewer_files.cpp: volumes, their renderers and splat sets.
  void info(const std::string& text);
  void error(const std::string& text);
  void adopt(LoadedVolume loaded, bool newCamera);
  // `keepView`: another volume of the same file (paging through frames): the camera, crop and
  // transfer function stay.
  // False when another load is still running (the user is told).
  bool startLoad(const std::string& path, const LoadOptions& load = {}, bool keepView = false);
  // The file's next (+1) or previous (-1) volume, round the end: 4D NIfTI, DICOM volumes.
  void stepFrame(int step);
  // The file's next (+1) or previous (-1) channel, round the end: RGB, OME-TIFF channels.
  void stepChannel(int step);
  LoadOptions pageBase() const;
  void requestPage(const LoadOptions& load);
  void stepPage(int LoadOptions::*which, int count, int step);
  // Another series of the open DICOM folder (Volume::seriesChoices), as --series opens it.
  void openSeries(const std::string& id);
  void respace(const glm::dvec3& spacing);
  void pollLoad();
  LodRenderer::Factory rendererFactory();
  // One level's renderer: ViewerConfig::rendererFactory's, else settings_.renderer's kind.
  std::unique_ptr<Renderer> makeRenderer();
  void switchRendererIfAsked();
  bool takeBuiltSplats();
  void openDialog();
  // The file dialog to save the volume on screen, and the save it starts (viewer_files.cpp).
  void saveDialog();
  void startSave(const std::string& path);
  void pollSave();
  // The volume's file read again (F5, "Reload", a change seen while watching): the same page,
  // camera and transfer function, unless the grid changed.
  void reload();

  // viewer_capture.cpp: pictures written to files.
  void screenshot(const glm::ivec2& fb);
  // Whether a screenshot under way, queued or being written will write `path`.
  bool shotPathPromised(const std::string& path) const;
  // A capture under way or waiting: a screenshot, a queued one, a turntable.
  bool capturing() const {
    return capture_.active || !queuedShots_.empty() || turntable_.total > 0;
  }
  glm::ivec2 captureSize(const glm::ivec2& fb) const;
  // `format`: "png" (a folder of frames), "mp4" or "webm" (a video at `fps`).
  // `tour`: through the camera bookmarks (with their clip regions) instead of about view-up.
  void startTurntable(int frames, const std::string& format, int fps, bool tour = false);
  // The turntable's next frame as a capture, its picture handed to the sink.
  void nextTurntableCapture(const glm::ivec2& fb);
  // This UI frame's share of the capture under way (starting the turntable's next frame when
  // none is); true when a picture was finished (and written or handed on).
  bool captureStep(const glm::ivec2& fb, bool activity);
  void finishCapture(const glm::ivec2& fb);
  void turntableFrameDone(Image8 image);
  void stopTurntable(const std::string& why);
  // Writes a screenshot's picture on a worker (one at a time); pollScreenshot says when it is.
  void writeScreenshot(const std::string& path, Image8 image);
  void pollScreenshot(bool wait = false);

  // viewer_panels.cpp: the panels, key commands and bookmarks.
  void drawPanels(const glm::ivec2& fb, bool* screenshotNow);
  void applyCommands(const glm::ivec2& fb, bool* screenshotNow);
  void showAxisView(AxisView v, const glm::ivec2& fb);
  // The window's size in window coordinates (the cursor's; the framebuffer may be larger).
  glm::ivec2 windowSize() const;
  // The probe line under the cursor, and a double-click's new centre of rotation.
  void updateProbe(glm::ivec2 size);
  void centreOnCursor();
  // The M key: the point under the cursor becomes the mark distances are measured from.
  void markUnderCursor();
  // The axes were switched on or off (the layout log says so).
  void axesSwitched();
  void copyView();
  void applySessionEdits(const SessionEdits& e, const glm::ivec2& fb, bool* screenshotNow);
  SessionView sessionView();
  void saveBookmarks();

  platform::GlfwWindowContext& window_;
  ViewerConfig config_;
  ViewerSettings saved_;
  Clock::time_point epoch_ = Clock::now();
  gl::ShaderLibrary shaders_;
  // The level-of-detail renderers' programs, one set for all (a level compiles nothing twice).
  std::shared_ptr<SplatProgramSet> splatPrograms_;
  LoadedVolume current_;
  // Big splat sets are uploaded on a worker bound to it (null: on this thread); before lod_,
  // whose uploads end before it goes.
  std::unique_ptr<platform::UploadContext> uploadContext_;
  LodRenderer lod_;
  RendererKind rendererKind_ = RendererKind::Splat;
  std::string renderError_;  // the last render failure, until a render succeeds
  LodPolicy policy_;
  // The moving level drawFrame drew and its render time, reported to the policy with the rest of
  // the UI frame (panels, present and swap, a real share of it on llvmpipe; the limit is on UI
  // frames); level -1: none.
  int movingLevelDrawn_ = -1;
  double movingRenderMs_ = 0.0;
  ProgressiveRefinement refinement_;
  ImagePresenter presenter_;
  CameraController controller_;
  RenderSettings settings_;
  WindowInput input_;
  ImGuiLayer imgui_;
  ControlPanel panel_;
  SessionPanel session_;
  CursorProbe probe_;
  LiveTransferFunction liveTf_;  // after current_ and lod_: its worker ends before they go
  FileDialog fileDialog_;
  StatusMessages messages_;
  VolumeLoadJob loadJob_;
  VolumeSaveJob saveJob_;
  std::optional<VoxelRange> saveCrop_;  // the crop box's voxels when the save dialog opened
  FileWatch fileWatch_;                 // the stamp of the file on screen
  bool watchFile_ = false;              // reload when it changes (--watch, the panel)
  bool loadIsReload_ = false;           // the load running reads the file on screen again
  bool keysHelp_ = false;               // the keys window is shown (F1)
  bool keysPrinted_ = false;            // what the layout log last said of it
  bool loadKeepsView_ = false;          // the load running pages through the current file's frames
  bool loadKeepsTf_ = false;  // the load running opens the current file with a new spacing
  LoadOptions pageTarget_;    // the page last asked for
  std::optional<LoadOptions> queuedPage_;       // asked for while another page loaded
  std::map<int, TransferFunction> channelTfs_;  // each channel's function while paging
  BookmarkStore bookmarks_;
  WindowTurntable turntable_;
  PendingCapture capture_;
  std::deque<PendingCapture> queuedShots_;  // screenshots asked for while another capture ran
  // A screenshot's PNG being encoded and written on a worker (a large one takes longer than a UI
  // frame may), and its file; the future's destructor waits for it, so a file begun is finished
  // on exit.
  std::future<void> shotWrite_;
  std::string shotPath_;
  std::string recorded_;  // camera path lines, when recording

  FrameStats frameStats_;
  bool levelOfDetail_ = true;
  bool axes_ = true;             // the orientation axes in the corner
  bool printLayout_ = false;     // EWAVIEW_PRINT_LAYOUT=1: layout and frame lines on stdout
  bool frameLog_ = false;        // EWAVIEW_FRAME_LOG=1: every frame's time on stderr
  double levelRenderMs_ = -1.0;  // this frame's renderLevel time for the log; -1: none
  bool fullSplatsArrived_ = false;
  bool fullLevelAsked_ = false;  // the full level's build was asked for before the first picture
  bool splatsUploaded_ = false;  // this frame put a worker's splat set in place
  bool calibrate_ = false;       // the next full frame picks the first moving level
  bool refineFailed_ = false;    // retried after the next change, not every frame
  std::optional<Classification> fullBuildFor_;  // the last full splat set asked of the worker
  int reportedRefinement_ = 0;                  // RefinementReport::index last shown and logged
  uint64_t renderedTf_ = 0;
  bool hasNvx_ = false;
  bool buildPending_ = false;
  uint64_t settingsRevision_ = 0;
  bool hasImage_ = false;
  uint64_t renderedCamera_ = 0;
  uint64_t renderedSettings_ = 0;
  glm::ivec2 renderedSize_{0, 0};
  glm::ivec2 lastFrameSize_{0, 0};  // the framebuffer's size at the last UI frame
  bool imagesPending_ = false;      // a new size's images are being made for the moving level
  glm::ivec2 policySize_{0, 0};     // the window size policy_'s measurements were made at
  bool presentNext_ = false;        // the last UI frame left its new picture to this one
  bool pictureShown_ = false;       // a picture has been presented
  Clock::time_point lastChange_ = Clock::now();
};

}  // namespace ewa
