// Camera bookmarks: JSON form, file names and atomic saving.
#include "io/camera_bookmarks.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/clip_region_json.h"
#include "io/side_file.h"

namespace ewa {

namespace {

using nlohmann::json;

json vec3Json(const glm::dvec3& v) {
  return json::array({v.x, v.y, v.z});
}

glm::dvec3 vec3From(const json& j, const char* key) {
  const json& v = j.at(key);
  if (!v.is_array() || v.size() != 3)
    throw std::runtime_error(std::string(key) + " needs 3 numbers");
  glm::dvec3 out;
  for (int a = 0; a < 3; ++a) {
    out[a] = v[size_t(a)].get<double>();
    if (!std::isfinite(out[a])) throw std::runtime_error(std::string(key) + " is not finite");
  }
  return out;
}

}  // namespace

std::string bookmarksPathFor(const std::string& volumePath) {
  const std::filesystem::path p(volumePath);
  return (p.parent_path() / (p.stem().string() + ".bookmarks.json")).string();
}

std::string fallbackBookmarksPath(const std::string& volumePath, const std::string& configDir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path absolute = fs::absolute(volumePath, ec);
  if (ec) absolute = volumePath;
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016zx",
                std::hash<std::string>{}(absolute.lexically_normal().string()));
  return (fs::path(configDir) / "bookmarks" /
          (fs::path(volumePath).stem().string() + "." + hash + ".bookmarks.json"))
      .string();
}

std::string BookmarkPlaces::read() const {
  namespace fs = std::filesystem;
  std::error_code ec;
  return !beside.empty() &&
                 (fs::exists(beside, ec) || fallback.empty() || !fs::exists(fallback, ec))
             ? beside
             : fallback;
}

BookmarkPlaces bookmarkPlaces(const std::string& volumePath, const std::string& name,
                              const std::string& configDir) {
  BookmarkPlaces places;
  if (!volumePath.empty()) places.beside = bookmarksPathFor(volumePath);
  if (!configDir.empty())
    places.fallback =
        fallbackBookmarksPath(volumePath.empty() ? "synthetic-" + name : volumePath, configDir);
  return places;
}

std::vector<TourStop> tourStopsOf(const std::vector<CameraBookmark>& bookmarks) {
  std::vector<TourStop> stops;
  for (const CameraBookmark& b : bookmarks) stops.push_back({b.camera, b.clip});
  return stops;
}

std::string bookmarksToJson(const std::vector<CameraBookmark>& bookmarks) {
  json list = json::array();
  for (const CameraBookmark& b : bookmarks) {
    json j;
    j["name"] = b.name;
    j["position"] = vec3Json(b.camera.position);
    j["focal_point"] = vec3Json(b.camera.focalPoint);
    j["view_up"] = vec3Json(b.camera.viewUp);
    j["view_angle"] = b.camera.viewAngleDeg;
    j["orthographic"] = b.camera.orthographic;
    if (b.clip.active() || !b.clip.planes.empty()) j["clip"] = clipRegionToJson(b.clip);
    list.push_back(j);
  }
  return json{{"bookmarks", list}}.dump(2) + "\n";
}

std::vector<CameraBookmark> bookmarksFromJson(const std::string& text, const std::string& name) {
  std::vector<CameraBookmark> out;
  try {
    const json doc = json::parse(text);
    const json& list = doc.at("bookmarks");
    if (!list.is_array()) throw std::runtime_error("\"bookmarks\" must be a list");
    for (const json& j : list) {
      CameraBookmark b;
      b.name = j.at("name").get<std::string>();
      b.camera.position = vec3From(j, "position");
      b.camera.focalPoint = vec3From(j, "focal_point");
      b.camera.viewUp = vec3From(j, "view_up");
      b.camera.viewAngleDeg = j.value("view_angle", 30.0);
      b.camera.orthographic = j.value("orthographic", false);
      if (j.contains("clip")) b.clip = clipRegionFromJson(j.at("clip"));
      if (!b.camera.valid())
        throw std::runtime_error("bookmark '" + b.name + "' is not a valid camera");
      out.push_back(std::move(b));
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(name + ": " + problemText(e));
  }
  return out;
}

std::vector<CameraBookmark> loadBookmarks(const std::string& path) {
  if (!std::filesystem::exists(path)) return {};
  return bookmarksFromJson(readSideFile(path, "bookmarks file"), path);
}

void saveBookmarks(const std::string& path, const std::vector<CameraBookmark>& bookmarks,
                   bool makeParents) {
  writeFileAtomically(path, bookmarksToJson(bookmarks), makeParents);
}

}  // namespace ewa
