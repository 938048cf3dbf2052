// --pick: the pixel's ray through the scene, as --output would draw it, printed as JSON.
#include "app/pick_output.h"

#include <nlohmann/json.hpp>

namespace ewa {

std::string pickJson(const Volume& volume, const TransferFunction& tf, const Options& options) {
  const Camera camera = initialCamera(volume, options);
  const glm::dvec2 pixel = *options.pick;
  const PickResult r = pickInPicture(volume, tf, options.render, camera, options.width,
                                     options.height, pixel + glm::dvec2(0.5));
  nlohmann::ordered_json j;  // keeps the documented key order
  j["pixel"] = {pixel.x, pixel.y};
  j["hit"] = r.hit;
  if (r.hit) {
    const glm::i64vec3 voxel = nearestVoxel(volume, r.index);
    j["world"] = {r.world.x, r.world.y, r.world.z};
    j["index"] = {r.index.x, r.index.y, r.index.z};
    j["voxel"] = {voxel.x, voxel.y, voxel.z};
    j["value"] = r.value;
    j["opacity"] = r.opacity;
    j["distance"] = r.distance;
  }
  return j.dump();
}

}  // namespace ewa
