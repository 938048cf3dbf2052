// Brick faces as world-space clipping planes through the index planes between voxel layers.
#include "dist/brick_clip.h"

#include <glm/geometric.hpp>

namespace ewa::dist {

std::string addBrickPlanes(const Volume& volume, const VoxelBox& brick, ClipRegion* clip) {
  const auto& dims = volume.dims();
  std::vector<ClipPlane> planes;
  for (int a = 0; a < 3; ++a) {
    // World direction of data axis a: the direction's column a.
    const glm::dvec3 axis = glm::normalize(volume.direction()[a]);
    for (int side = 0; side < 2; ++side) {
      const int64_t at = side == 0 ? brick.low[a] : brick.high[a];
      if (at <= 0 || at >= dims[a]) continue;  // the volume's own face: not cut
      glm::dvec3 index(0.0);
      index[a] = double(at) - 0.5;
      ClipPlane plane;
      plane.point = volume.worldPosition(index.x, index.y, index.z);
      plane.normal = side == 0 ? axis : -axis;
      planes.push_back(plane);
    }
  }
  if (clip->planes.size() + planes.size() > ClipRegion::kMaxPlanes)
    return "the brick needs " + std::to_string(planes.size()) + " clipping planes beside the " +
           std::to_string(clip->planes.size()) + " given, more than " +
           std::to_string(ClipRegion::kMaxPlanes) + "; give fewer --clip-plane";
  clip->planes.insert(clip->planes.end(), planes.begin(), planes.end());
  return "";
}

}  // namespace ewa::dist
