// The bricks' visibility order from a camera, the same on every rank: front to back by the
// eye's side of each k-d cut (perspective) or the view direction (orthographic).
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "core/camera.h"
#include "core/volume.h"
#include "dist/brick_split.h"

namespace ewa::dist {

// The camera in voxel index coordinates (where the split's planes are): the eye, and the view
// direction (eye towards the focal point; not of unit length).
struct IndexView {
  bool orthographic = false;
  glm::dvec3 eye{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
};

// index = D^T (world - origin) / spacing for the volume's direction D.
IndexView indexView(const Camera& camera, const Volume& volume);
// The same for a grid known by its origin, direction and spacing (a distributed run's whole
// volume, which no process holds).
IndexView indexView(const Camera& camera, const glm::dvec3& origin, const glm::dmat3& direction,
                    const glm::dvec3& spacing);

// Where cut `node` lies in index coordinates: halfway between its voxel layers plane - 1 and
// plane, the face the two bricks' crop boxes share.
inline double cutCoordinate(const SplitNode& node) {
  return double(node.plane) - 0.5;
}

// Brick indices front to back. Exact for a k-d split: at each cut the child on the eye's side
// (perspective) or the child the view direction enters first (orthographic) is in front of
// every ray's part in the other; on the plane, or with the view along it, either order is
// right and the lower child is taken.
std::vector<int> visibilityOrder(const BrickSplit& split, const IndexView& view);

}  // namespace ewa::dist
