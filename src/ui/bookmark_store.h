// BookmarkStore: the camera bookmarks of the volume on screen and where they are kept.
#pragma once

#include <string>
#include <vector>

#include "io/camera_bookmarks.h"

namespace ewa {

// Bookmarks live beside the volume file (NAME.bookmarks.json); when that folder is read-only,
// or the volume is synthetic, they go to the settings folder instead.
class BookmarkStore {
 public:
  // Reads the bookmarks of a volume (`path` empty: synthetic, keyed by `name`). Returns an
  // error message (the list stays empty) or "".
  std::string open(const std::string& path, const std::string& name, const std::string& configDir);
  // Writes the list, falling back to the settings folder when the volume's folder refuses.
  // Returns an error message or ""; `*note` says where they went when that changed.
  std::string save(std::string* note);

  std::vector<CameraBookmark>& list() { return bookmarks_; }
  const std::string& path() const { return path_; }

 private:
  std::vector<CameraBookmark> bookmarks_;
  std::string path_;       // where they are read from and written to; empty: nowhere
  BookmarkPlaces places_;  // beside the volume and in the settings folder
};

}  // namespace ewa
