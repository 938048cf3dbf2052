// FileDialog: an ImGui window to pick a volume file: folder listing, extension filter, path box.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/file_listing.h"

namespace ewa {

class FileDialog {
 public:
  // Shows the dialog at `folder` (the current folder when empty or unreadable).
  void open(const std::string& folder);
  bool isOpen() const { return open_; }
  // Draws the dialog (between ImGui frames); returns the chosen file once, and closes.
  std::optional<std::string> draw();

 private:
  void changeFolder(const std::string& folder);

  bool open_ = false;
  bool justOpened_ = false;
  bool allFiles_ = false;  // show every file, not only volume extensions
  std::string folder_;
  std::vector<DirEntry> entries_;
  std::string error_;
  char pathBuffer_[1024] = {};
  int selected_ = -1;
};

}  // namespace ewa
