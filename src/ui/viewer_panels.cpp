// ViewerWindow's panels and commands: the control, session and file panels, key commands,
// dropped files, bookmarks and the settings saved on exit.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "core/camera_views.h"
#include "core/view_options_text.h"
#include "io/atomic_file.h"
#include "io/file_listing.h"
#include "ui/axes_overlay.h"
#include "ui/clip_panel.h"
#include "ui/crop_box_handles.h"
#include "ui/keys_help.h"
#include "ui/viewer_window.h"

namespace ewa {

void ViewerWindow::drawPanels(const glm::ivec2& fb, bool* screenshotNow) {
  imgui_.beginFrame();
  Camera camera = controller_.camera();
  // The session's and the clip region's sections sit in the panel at the places it gives them.
  const SessionView session = sessionView();
  SessionEdits sessionEdits;
  ClipPanelEdits clip;
  PanelSections sections;
  sections.status = [&] { session_.drawStatus(session); };
  sections.files = [&] { session_.drawFiles(session, sessionEdits); };
  sections.clip = [&] {
    clip = drawClipControls(settings_.clip, current_.volume->worldBoundsMin(),
                            current_.volume->worldBoundsMax(), controller_.camera());
  };
  sections.captures = [&] { session_.drawCaptures(session, sessionEdits); };
  const PanelEdits edits =
      panel_.draw(settings_, camera, levelOfDetail_, axes_, frameStats_, sections);
  if (edits.axes) axesSwitched();
  if (edits.frameStep != 0) stepFrame(edits.frameStep);
  if (edits.channelStep != 0) stepChannel(edits.channelStep);
  if (edits.series) openSeries(*edits.series);
  if (edits.spacing) respace(*edits.spacing);
  if (edits.camera) controller_.setCamera(camera);
  if (edits.resetCamera) controller_.reset();
  if (edits.copyView) copyView();
  if (edits.keysHelp) keysHelp_ = !keysHelp_;
  if (edits.axisView) showAxisView(*edits.axisView, fb);
  if (edits.tfPreset) liveTf_.applyPreset(*edits.tfPreset);
  if (edits.settings) ++settingsRevision_;
  // A dragged crop box or plane renders like a moving camera: coarse levels until it stops.
  const glm::dvec3 extent = current_.volume->worldBoundsMax() - current_.volume->worldBoundsMin();
  const CropHandleEdits handles = drawCropBoxHandles(
      settings_.clip, controller_.camera(), 0.01 * std::min({extent.x, extent.y, extent.z}));
  if (clip.changed || handles.changed) ++settingsRevision_;
  if (const TransferFunction* tf = liveTf_.drawAndApply(lod_, splatClassification(settings_)))
    current_.tf = *tf;
  switchRendererIfAsked();
  applySessionEdits(sessionEdits, fb, screenshotNow);
  drawKeysHelp(&keysHelp_);
  if (printLayout_ && keysPrinted_ != keysHelp_) {  // F1, the button or the window's close box
    keysPrinted_ = keysHelp_;
    std::printf("keys %s\n", keysHelp_ ? "on" : "off");
    std::fflush(stdout);
  }
  if (const auto chosen = fileDialog_.draw()) {
    if (fileDialog_.purpose() == FileDialog::Purpose::SaveVolume)
      startSave(*chosen);
    else
      startLoad(*chosen);
  }
  if (frameStats_.refineProgress >= 0.0) drawRefinementOverlay(frameStats_.refineProgress);
  const glm::ivec2 size = windowSize();
  updateProbe(size);
  probe_.draw(frameStats_.refineProgress >= 0.0, controller_.camera(), size);
  if (axes_) drawAxesOverlay(controller_.camera(), current_.volume->patientFrame(), size);
}

// The view as options on the clipboard (and in the panel and on stderr, where a script or a
// person without a clipboard finds them).
void ViewerWindow::copyView() {
  const std::string text =
      viewOptionsText(controller_.camera(), window_.framebufferSize(), settings_.clip);
  glfwSetClipboardString(window_.window(), text.c_str());
  info("view copied: " + text);
}

void ViewerWindow::axesSwitched() {
  if (!printLayout_) return;
  std::printf("axes %s\n", axes_ ? "on" : "off");
  std::fflush(stdout);
}

glm::ivec2 ViewerWindow::windowSize() const {
  glm::ivec2 size(0);
  glfwGetWindowSize(window_.window(), &size.x, &size.y);
  return size;
}

void ViewerWindow::updateProbe(glm::ivec2 size) {
  GLFWwindow* w = window_.window();
  std::optional<glm::dvec2> cursor;
  // Over the picture only: not over a panel, not while a drag moves the camera.
  if (!controller_.dragging() && !ImGui::GetIO().WantCaptureMouse &&
      glfwGetWindowAttrib(w, GLFW_HOVERED)) {
    glm::dvec2 at;
    glfwGetCursorPos(w, &at.x, &at.y);
    if (at.x >= 0.0 && at.y >= 0.0 && at.x < size.x && at.y < size.y) cursor = at;
  }
  const ProbeStamp stamp{current_.volume.get(), controller_.revision(), settingsRevision_,
                         liveTf_.revision()};
  probe_.update(*current_.volume, current_.tf, settings_, controller_.camera(), size, cursor,
                stamp);
  if (printLayout_ && probe_.changed()) {
    std::printf("probe %s\n", probe_.text().c_str());
    std::fflush(stdout);
  }
}

void ViewerWindow::markUnderCursor() {
  const PickResult& pick = probe_.last();
  if (pick.hit) {
    probe_.setMark(pick.world);
    char text[160];
    std::snprintf(text, sizeof text,
                  "mark at %.4g, %.4g, %.4g: the probe line gives the distance from it (M on "
                  "empty space clears it)",
                  pick.world.x, pick.world.y, pick.world.z);
    info(text);
    if (printLayout_) {
      std::printf("mark %g %g %g\n", pick.world.x, pick.world.y, pick.world.z);
      std::fflush(stdout);
    }
  } else if (probe_.mark()) {
    probe_.setMark(std::nullopt);
    info("mark cleared");
  } else {
    info("nothing under the cursor to mark");
  }
}

void ViewerWindow::centreOnCursor() {
  const glm::ivec2 size = windowSize();
  const PickResult pick =
      pickInPicture(*current_.volume, current_.tf, settings_, controller_.camera(), size.x, size.y,
                    glm::dvec2(input_.doubleClickX(), input_.doubleClickY()));
  if (!pick.hit) {
    info("nothing under the cursor to centre on");
    return;
  }
  controller_.setCamera(centredOn(controller_.camera(), pick.world));
  if (printLayout_) {
    std::printf("centre %g %g %g\n", pick.world.x, pick.world.y, pick.world.z);
    std::fflush(stdout);
  }
}

// Window size, render settings, recent files and the panel layout, for the next run.
void ViewerWindow::saveSettings() {
  if (config_.configDir.empty()) return;
  int w = 0, h = 0;
  glfwGetWindowSize(window_.window(), &w, &h);
  if (w > 0 && h > 0) {
    saved_.windowWidth = w;
    saved_.windowHeight = h;
  }
  saved_.filter = settings_.filter;
  saved_.renderMode = renderModeName(settings_.mode);
  saved_.cutoff = settings_.cutoff;
  saved_.depthCutoff = settings_.depthCutoff;
  saved_.kernelWidth = settings_.kernelWidth;
  saved_.classification = classificationModeName(settings_.classification.mode);
  saved_.slabPreintegration = settings_.slabPreintegration;
  saved_.slabSamples = settings_.slabSamples;
  saved_.prefilter = settings_.classification.prefilter;
  saved_.postNormals = postNormalsName(settings_.postNormals);
  saved_.slabThickness = settings_.slabThickness;
  saved_.coarseSlabs = settings_.coarseSlabs;
  saved_.background = settings_.background;
  saved_.levelOfDetail = levelOfDetail_;
  saved_.axes = axes_;
  saved_.clip = settings_.clip;
  saved_.clipVolume = current_.path.empty() ? "synthetic:" + current_.name : current_.path;
  std::string problem;
  saved_.lastTransferFunction =
      liveTf_.keep(config_.configDir, saved_.lastTransferFunction, &problem);
  if (!problem.empty()) std::cerr << "ewaview: " << problem << "\n";
  try {
    saveViewerSettings(settingsPathIn(config_.configDir), saved_);
    writeFileAtomically(imguiIniPathIn(config_.configDir), imgui_.saveLayout(), true);
  } catch (const std::exception& e) {
    std::cerr << "ewaview: " << e.what() << "\n";
  }
}

void ViewerWindow::applyCommands(const glm::ivec2& fb, bool* screenshotNow) {
  for (KeyCommand c : input_.takeCommands()) {
    if (printLayout_) {  // the scripted window test's log: which key commands arrived
      std::printf("command %d\n", int(c));
      std::fflush(stdout);
    }
    switch (c) {
      case KeyCommand::Screenshot:
        *screenshotNow = true;
        break;
      case KeyCommand::OpenFile:
        openDialog();
        break;
      case KeyCommand::SaveVolume:
        saveDialog();
        break;
      case KeyCommand::CopyView:
        copyView();
        break;
      case KeyCommand::Reload:
        reload();
        break;
      case KeyCommand::KeysHelp:
        keysHelp_ = !keysHelp_;
        break;
      case KeyCommand::Undo:
      case KeyCommand::Redo:
        liveTf_.stepHistory(c == KeyCommand::Undo ? -1 : 1);
        break;
      case KeyCommand::CentreOnCursor:
        centreOnCursor();
        break;
      case KeyCommand::MarkPoint:
        markUnderCursor();
        break;
      case KeyCommand::ToggleAxes:
        axes_ = !axes_;
        axesSwitched();
        break;
      case KeyCommand::NextFrame:
      case KeyCommand::PreviousFrame:
        stepFrame(c == KeyCommand::NextFrame ? 1 : -1);
        break;
      case KeyCommand::NextChannel:
      case KeyCommand::PreviousChannel:
        stepChannel(c == KeyCommand::NextChannel ? 1 : -1);
        break;
      default: {
        const int index = int(c) - int(KeyCommand::ViewPlusX);
        showAxisView(kAxisViews[index], fb);
      }
    }
  }
  for (const std::string& path : input_.takeDroppedPaths()) {
    // A .json file is a transfer function (or a ParaView preset), never a volume.
    if (hasExtension(path, {".json"})) {
      liveTf_.loadFile(path);
      continue;
    }
    startLoad(path);  // one volume at a time: the first drop wins, others say "still loading"
    break;
  }
}

void ViewerWindow::showAxisView(AxisView v, const glm::ivec2& fb) {
  const Volume& volume = *current_.volume;
  controller_.setCamera(
      cameraForAxisView(controller_.camera(), v, volume.worldBoundsMin(), volume.worldBoundsMax(),
                        fb.y > 0 ? double(fb.x) / fb.y : 1.0, volume.patientFrame()));
}

void ViewerWindow::applySessionEdits(const SessionEdits& e, const glm::ivec2& fb,
                                     bool* screenshotNow) {
  if (e.openDialog) openDialog();
  if (e.saveDialog) saveDialog();
  if (e.reload) reload();
  if (e.watch) {
    watchFile_ = *e.watch;
    info(watchFile_ ? "reloading " + current_.name + " whenever its file changes"
                    : "no longer watching " + current_.name);
  }
  if (e.openPath) startLoad(*e.openPath);
  if (e.addBookmark) {
    bookmarks_.list().push_back({*e.addBookmark, controller_.camera(), settings_.clip});
    saveBookmarks();
  }
  std::vector<CameraBookmark>& marks = bookmarks_.list();
  if (e.applyBookmark >= 0 && e.applyBookmark < int(marks.size())) {
    controller_.setCamera(marks[size_t(e.applyBookmark)].camera);
    if (settings_.clip != marks[size_t(e.applyBookmark)].clip) {
      settings_.clip = marks[size_t(e.applyBookmark)].clip;  // the view as bookmarked
      ++settingsRevision_;
    }
  }
  if (e.deleteBookmark >= 0 && e.deleteBookmark < int(marks.size())) {
    marks.erase(marks.begin() + e.deleteBookmark);
    saveBookmarks();
  }
  if (e.screenshot) *screenshotNow = true;
  if (e.captureScale) saved_.captureScale = *e.captureScale;
  if (e.turntableFrames > 0 && turntable_.total == 0)
    startTurntable(e.turntableFrames, e.turntableFormat, e.turntableFps, e.tour);
  if (e.cancelTurntable) stopTurntable("");
}

SessionView ViewerWindow::sessionView() {
  SessionView v;
  v.recentFiles = &saved_.recentFiles;
  v.bookmarks = &bookmarks_.list();
  v.fromFile = !current_.path.empty();
  v.captureScale = saved_.captureScale;
  v.watching = watchFile_;
  v.bookmarksPath = bookmarks_.path();
  v.loading = loadJob_.running();
  v.loadingPath = loadJob_.path();
  v.loadingSeconds = loadJob_.elapsedSeconds();
  if (buildPending_) v.busyText = "building splats for " + current_.name + "...";
  if (saveJob_.running()) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, " (%.1f s)", saveJob_.elapsedSeconds());
    v.busyText = "saving " + std::filesystem::path(saveJob_.path()).filename().string() + seconds;
  }
  v.turntableDone = turntable_.done;
  v.turntableTotal = turntable_.total;
  v.messages = &messages_.current(now());
  return v;
}

void ViewerWindow::saveBookmarks() {
  std::string note;
  const std::string problem = bookmarks_.save(&note);
  if (!problem.empty()) error(problem);
  if (!note.empty()) info(note);
}

}  // namespace ewa
