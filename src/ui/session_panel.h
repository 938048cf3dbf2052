// SessionPanel: the panel's file, bookmark and capture sections, progress and messages.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/camera_bookmarks.h"
#include "ui/layout_log.h"
#include "ui/status_messages.h"

namespace ewa {

// What the panel shows this frame.
struct SessionView {
  const std::vector<std::string>* recentFiles = nullptr;
  const std::vector<CameraBookmark>* bookmarks = nullptr;
  std::string bookmarksPath;  // where they are saved
  bool fromFile = false;      // the volume came from a file (not synthetic): it can be reloaded
  bool watching = false;      // reloaded whenever its file changes
  bool loading = false;       // a volume is being opened
  std::string loadingPath;
  double loadingSeconds = 0.0;
  std::string busyText;                       // other long work ("building splats"), or empty
  int turntableDone = 0, turntableTotal = 0;  // a turntable in progress when total > 0
  const std::vector<StatusMessages::Message>* messages = nullptr;
  int captureScale = 1;  // screenshots and turntables at this many times the window's size
};

// What the user asked for this frame.
struct SessionEdits {
  bool openDialog = false;
  bool saveDialog = false;                 // save the volume on screen as NRRD
  bool reload = false;                     // read the volume's file again
  std::optional<bool> watch;               // "reload when the file changes" switched
  std::optional<std::string> openPath;     // a recent file
  std::optional<std::string> addBookmark;  // name of the bookmark to add at the current view
  int applyBookmark = -1;
  int deleteBookmark = -1;
  bool screenshot = false;
  int turntableFrames = 0;              // > 0: start a turntable of that many frames
  std::string turntableFormat = "png";  // "png" (a folder of frames), "mp4" or "webm"
  int turntableFps = 30;                // frames per second of a video
  bool tour = false;                    // the frames fly through the bookmarks instead
  bool cancelTurntable = false;
  std::optional<int> captureScale;  // the size of pictures written changed (1 to 4 windows)
};

class SessionPanel {
 public:
  // The sections, drawn into the current window (the control panel's, at the places it gives
  // them: PanelSections); what the user asked for is added to `edits`.
  // Loading progress, busy work and messages.
  void drawStatus(const SessionView& view);
  // "File": open, save, reload, watch, recent files.
  void drawFiles(const SessionView& view, SessionEdits& edits);
  // "Camera bookmarks" and "Capture" (screenshot, turntable, tour).
  void drawCaptures(const SessionView& view, SessionEdits& edits);
  // EWAVIEW_PRINT_LAYOUT: the places of the sections' headers and the Tour button on stdout,
  // for the window test ("section-file X Y W H", "capture-header ...", "tour-button ...").
  void setPrintLayout(bool on) { layout_.setOn(on); }

 private:
  void drawBookmarks(const SessionView& view, SessionEdits& edits);
  void drawCapture(const SessionView& view, SessionEdits& edits);

  char bookmarkName_[64] = "view 1";
  int turntableFrames_ = 36;
  int turntableFormat_ = 0;  // index into the panel's format list
  int turntableFps_ = 30;
  LayoutLog layout_;
};

}  // namespace ewa
