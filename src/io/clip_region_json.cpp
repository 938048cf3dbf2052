// ClipRegion <-> JSON, checked as strictly as the command line checks --crop and --clip-plane.
#include "io/clip_region_json.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace ewa {

using nlohmann::json;

namespace {

json vec3Json(const glm::dvec3& v) {
  return json::array({v.x, v.y, v.z});
}

glm::dvec3 vec3From(const json& j, const char* key) {
  const std::vector<double> v = j.at(key).get<std::vector<double>>();
  if (v.size() != 3) throw std::runtime_error(std::string("clip: \"") + key + "\" needs 3 numbers");
  for (double x : v)
    if (!std::isfinite(x))
      throw std::runtime_error(std::string("clip: \"") + key + "\" is not finite");
  return {v[0], v[1], v[2]};
}

}  // namespace

json clipRegionToJson(const ClipRegion& r) {
  json planes = json::array();
  for (const ClipPlane& p : r.planes)
    planes.push_back(
        {{"point", vec3Json(p.point)}, {"normal", vec3Json(p.normal)}, {"enabled", p.enabled}});
  return {
      {"crop",
       {{"enabled", r.cropEnabled}, {"min", vec3Json(r.cropMin)}, {"max", vec3Json(r.cropMax)}}},
      {"planes", planes}};
}

ClipRegion clipRegionFromJson(const json& j) {
  ClipRegion r;
  try {
    if (!j.is_object()) throw std::runtime_error("clip: must be a JSON object");
    if (j.contains("crop")) {
      const json& c = j.at("crop");
      r.cropEnabled = c.value("enabled", false);
      if (c.contains("min")) r.cropMin = vec3From(c, "min");
      if (c.contains("max")) r.cropMax = vec3From(c, "max");
      for (int a = 0; a < 3 && r.cropEnabled; ++a)
        if (!(r.cropMin[a] < r.cropMax[a]))
          throw std::runtime_error("clip: the crop box's min must be less than its max");
    }
    if (j.contains("planes")) {
      const json& list = j.at("planes");
      if (!list.is_array()) throw std::runtime_error("clip: \"planes\" must be a list");
      if (list.size() > ClipRegion::kMaxPlanes)
        throw std::runtime_error("clip: at most " + std::to_string(ClipRegion::kMaxPlanes) +
                                 " planes");
      for (const json& p : list) {
        ClipPlane plane;
        plane.point = vec3From(p, "point");
        plane.normal = vec3From(p, "normal");
        plane.enabled = p.value("enabled", true);
        if (!(glm::length(plane.normal) > 0.0))
          throw std::runtime_error("clip: a plane's normal is zero");
        r.planes.push_back(plane);
      }
    }
  } catch (const json::exception& e) {
    throw std::runtime_error(std::string("clip: ") + e.what());
  }
  return r;
}

}  // namespace ewa
