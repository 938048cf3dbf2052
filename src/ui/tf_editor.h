// TfEditor: the ImGui transfer-function editor: points over the histogram, presets, files.
#pragma once

#include <string>
#include <vector>

#include "core/transfer_function.h"
#include "core/undo_history.h"
#include "core/volume.h"
#include "io/paraview_colormap.h"
#include "ui/tf_canvas.h"

namespace ewa {

class TfEditor {
 public:
  // `savePath` is the initial text of the path field. The volume must outlive the editor.
  TfEditor(const Volume& volume, TransferFunction tf, std::string savePath);

  // Builds the editor window (between ImGuiLayer::beginFrame and render). Returns true when
  // the transfer function changed this frame.
  bool draw();

  const TransferFunction& transferFunction() const { return tf_; }
  // Undo (step < 0) or redo (step > 0) an edit in the next draw (Ctrl+Z, Ctrl+Y from the
  // window's keys; the editor's own buttons do the same). Every kind of edit is a step: a drag
  // or a typed value once it ends, a point added or removed, a preset, a loaded file.
  void requestHistoryStep(int step) { pendingStep_ = step; }
  // Loads a transfer function (or a ParaView preset file's first map) in the next draw: a JSON
  // file dropped on the window.
  void requestFile(const std::string& path) { pendingFile_ = path; }
  // Applies a preset (its name or key) in the next draw: the main panel's colour menu.
  void requestPreset(const std::string& name) { pendingPreset_ = name; }
  // True while a point is being dragged (a viewer may draw a coarser level meanwhile).
  bool dragging() const { return dragOpacity_ >= 0 || dragColor_ >= 0; }
  // Set by EWAVIEW_PRINT_LAYOUT=1 in the environment: prints "tf-canvas X Y W H" (window
  // pixels) to stdout whenever the plot moves, for the scripted window test.
  void setPrintLayout(bool on) { printLayout_ = on; }
  // The file last saved or loaded here (empty: none), and whether the function was edited
  // since then (so a viewer can keep unsaved edits on exit).
  const std::string& lastFile() const { return lastFile_; }
  bool editedSinceFile() const { return editedSinceFile_; }

 private:
  bool drawOpacityPlot();
  bool drawColorBar();
  bool drawSelectedPoint();
  bool drawPresets();
  bool drawFiles();
  bool drawHistory();
  bool loadPendingFile();
  bool applyPreset(const std::string& name);
  void reportError(const std::string& message);

  const Volume& volume_;
  TransferFunction tf_;
  TfCanvas canvas_;
  UndoHistory<TransferFunction> history_;
  int pendingStep_ = 0;
  std::string pendingFile_;
  std::string pendingPreset_;
  bool logHistogram_ = true;
  int dragOpacity_ = -1, dragColor_ = -1;          // point under the mouse drag, or -1
  int selectedOpacity_ = -1, selectedColor_ = -1;  // last point clicked, or -1
  float grabOffsetX_ = 0, grabOffsetY_ = 0;        // point centre minus cursor at the press
  std::vector<float> histogram_;                   // counts, linear
  char path_[512] = {};
  bool rescaleImport_ = true;
  std::vector<ImportedColorMap> imported_;
  int importedIndex_ = 0;
  std::string status_;
  bool statusIsError_ = false;
  bool printLayout_ = false;
  std::string lastFile_;
  bool editedSinceFile_ = false;
  bool justLoaded_ = false;
  float printedX_ = -1, printedY_ = -1;
};

}  // namespace ewa
