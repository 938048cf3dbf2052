// FileDialog: an ImGui window to pick a volume to open or a file to save it as: folder listing,
// extension filter, path box.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/file_listing.h"

namespace ewa {

class FileDialog {
 public:
  // What the chosen path is for: a volume (or folder) to open, or a .nrrd file to write.
  enum class Purpose { Open, SaveVolume };

  // Shows the dialog at `folder` (the current folder when empty or unreadable); for SaveVolume
  // the path field starts at `fileName` in that folder, and a non-empty `optionLabel` adds a
  // checkbox (ticked at first) read back by optionChecked.
  void open(const std::string& folder, Purpose purpose = Purpose::Open,
            const std::string& fileName = {}, const std::string& optionLabel = {});
  bool isOpen() const { return open_; }
  Purpose purpose() const { return purpose_; }
  bool optionChecked() const { return !optionLabel_.empty() && optionChecked_; }
  // Draws the dialog (between ImGui frames); returns the chosen path once, and closes. Saving,
  // a name without an extension gets ".nrrd", any other is refused in the dialog, and an
  // existing file is replaced only once confirmed.
  std::optional<std::string> draw();

 private:
  void changeFolder(const std::string& folder);
  // Enter or the Open/Save button on the typed path: a folder is entered, a file chosen.
  std::optional<std::string> accept();
  std::optional<std::string> drawReplacePrompt();

  bool open_ = false;
  bool justOpened_ = false;
  bool allFiles_ = false;  // show every file, not only volume extensions
  Purpose purpose_ = Purpose::Open;
  std::string folder_;
  std::vector<DirEntry> entries_;
  std::string error_;
  std::string replacing_;      // an existing file waiting for "Replace"
  std::string replacingText_;  // "NAME exists." (or both files of a .mhd pair)
  bool askReplace_ = false;
  std::string optionLabel_;
  bool optionChecked_ = true;
  char pathBuffer_[1024] = {};
  int selected_ = -1;
};

}  // namespace ewa
