// Camera bookmarks: named cameras kept in NAME.bookmarks.json beside the volume file.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/clip_region.h"

namespace ewa {

struct CameraBookmark {
  std::string name;
  Camera camera;
  ClipRegion clip;  // the crop box and planes shown with it (none in older files)
};

// "dir/name.bookmarks.json" beside "dir/name.ext" (like the .tf.json sidecar).
std::string bookmarksPathFor(const std::string& volumePath);
// Where bookmarks go when the volume's folder is not writable (shared, read-only data):
// "configDir/bookmarks/name.HASH.bookmarks.json", HASH from the volume's absolute path.
std::string fallbackBookmarksPath(const std::string& volumePath, const std::string& configDir);

// {"bookmarks": [{"name": "...", "position": [x,y,z], "focal_point": [...], "view_up": [...],
//   "view_angle": deg, "orthographic": false, "clip": {...} (see clip_region_json.h)}, ...]}
std::string bookmarksToJson(const std::vector<CameraBookmark>& bookmarks);
// Throws std::runtime_error("name: problem") for bad JSON, missing fields or an invalid camera.
std::vector<CameraBookmark> bookmarksFromJson(const std::string& text, const std::string& name);

// A missing file gives no bookmarks; a bad one throws std::runtime_error("path: problem").
std::vector<CameraBookmark> loadBookmarks(const std::string& path);
// Written atomically (temporary file and rename); throws std::runtime_error("path: problem").
void saveBookmarks(const std::string& path, const std::vector<CameraBookmark>& bookmarks,
                   bool makeParents = false);

}  // namespace ewa
