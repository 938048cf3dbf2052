// Visibility order of k-d bricks: a walk of the split tree, nearer child first.
#include "dist/visibility_order.h"

#include <glm/matrix.hpp>

namespace ewa::dist {

IndexView indexView(const Camera& camera, const Volume& volume) {
  return indexView(camera, volume.origin(), volume.direction(), volume.spacing());
}

IndexView indexView(const Camera& camera, const glm::dvec3& origin, const glm::dmat3& direction,
                    const glm::dvec3& spacing) {
  const glm::dmat3 toIndex = glm::transpose(direction);
  IndexView v;
  v.orthographic = camera.orthographic;
  v.eye = toIndex * (camera.position - origin) / spacing;
  v.direction = toIndex * (camera.focalPoint - camera.position) / spacing;
  return v;
}

namespace {

void walk(const BrickSplit& split, int child, const IndexView& view, std::vector<int>* out) {
  if (child < 0) {
    out->push_back(-1 - child);
    return;
  }
  const SplitNode& node = split.nodes[size_t(child)];
  const bool lowerFirst = view.orthographic ? !(view.direction[node.axis] < 0.0)
                                            : !(view.eye[node.axis] > cutCoordinate(node));
  walk(split, lowerFirst ? node.lower : node.upper, view, out);
  walk(split, lowerFirst ? node.upper : node.lower, view, out);
}

}  // namespace

std::vector<int> visibilityOrder(const BrickSplit& split, const IndexView& view) {
  std::vector<int> order;
  order.reserve(split.bricks.size());
  if (!split.bricks.empty()) walk(split, split.root, view, &order);
  return order;
}

}  // namespace ewa::dist
