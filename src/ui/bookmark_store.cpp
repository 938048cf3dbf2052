// BookmarkStore: reads and writes a volume's camera bookmarks, beside it or in the config.
#include "ui/bookmark_store.h"

#include <exception>
#include <filesystem>

namespace ewa {

std::string BookmarkStore::open(const std::string& path, const std::string& name,
                                const std::string& configDir) {
  bookmarks_.clear();
  volumePath_ = path;
  name_ = name;
  configDir_ = configDir;
  const std::string beside = path.empty() ? "" : bookmarksPathFor(path);
  const std::string fallback = configDir.empty() ? "" : fallbackBookmarksPath(key(), configDir);
  // Beside the volume unless only the fallback exists (saved there when the folder refused).
  path_ = !beside.empty() && (std::filesystem::exists(beside) || fallback.empty() ||
                              !std::filesystem::exists(fallback))
              ? beside
              : fallback;
  if (path_.empty()) return "";
  try {
    bookmarks_ = loadBookmarks(path_);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string BookmarkStore::save(std::string* note) {
  try {
    saveBookmarks(path_, bookmarks_);
    return "";
  } catch (const std::exception& e) {
    if (configDir_.empty()) return e.what();
  }
  const std::string fallback = fallbackBookmarksPath(key(), configDir_);
  try {
    saveBookmarks(fallback, bookmarks_, /*makeParents=*/true);
    if (fallback != path_ && note) *note = "volume folder not writable; bookmarks in " + fallback;
    path_ = fallback;
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace ewa
