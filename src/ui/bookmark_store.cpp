// BookmarkStore: reads and writes a volume's camera bookmarks, beside it or in the config.
#include "ui/bookmark_store.h"

#include <exception>

namespace ewa {

std::string BookmarkStore::open(const std::string& path, const std::string& name,
                                const std::string& configDir) {
  bookmarks_.clear();
  places_ = bookmarkPlaces(path, name, configDir);
  // Beside the volume unless only the fallback exists (saved there when the folder refused).
  path_ = places_.read();
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
    if (places_.fallback.empty()) return e.what();
  }
  const std::string& fallback = places_.fallback;
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
