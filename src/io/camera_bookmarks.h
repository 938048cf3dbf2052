// Camera bookmarks: named cameras kept in NAME.bookmarks.json beside the volume file.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/camera_tour.h"
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

// Where the window keeps the bookmarks of a volume (`volumePath`, or "" for a synthetic one
// named `name`): beside its file, and in the settings folder (keyed by the path, or
// "synthetic-NAME"); each empty where there is none (no file; no `configDir`).
struct BookmarkPlaces {
  std::string beside, fallback;
  // The one read: beside, unless only the fallback exists.
  std::string read() const;
};
BookmarkPlaces bookmarkPlaces(const std::string& volumePath, const std::string& name,
                              const std::string& configDir);

// The bookmarks' views as the stops of a camera tour, in order.
std::vector<TourStop> tourStopsOf(const std::vector<CameraBookmark>& bookmarks);

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
