// Post-classified slabs' covered length: the kernels' summed weight along a pixel's ray, ended at
// the data's box. Mirrored line for line by shaders/covered_length.glsl.
#pragma once

#include <algorithm>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/clip_region.h"
#include "core/volume.h"

namespace ewa {

class Camera;
struct Projection;

// The camera space of `volumeCamera` (a camera in the volume's frame) to voxel index coordinates.
glm::dmat4 cameraToIndex(const Volume& volume, const Camera& volumeCamera);

// The ray through `pixel` of `proj` in index coordinates: the point at depth z is
// origin + z * direction.
struct IndexRay {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0};
};
IndexRay indexRay(const glm::dmat4& cameraToIndex, const Projection& proj, const glm::dvec2& pixel);

// World length per unit of depth along the ray through `pixel`.
double rayStretch(const Projection& proj, const glm::dvec2& pixel);

// The depths of the ray x + z * y (index coordinates) inside `box` (the data's box,
// Volume::indexDataBox); empty if near > far.
RayInterval boxDepths(const glm::dvec3& origin, const glm::dvec3& direction, const DataBox& box);

// The covered length of the ray between depths `a` and `b`, given the kernels' summed weight
// `weight` there (their covered length, which the clip region has cut already) and the depths
// `inBox` (boxDepths) inside the data's box: the weight inside, none outside, and where a face
// cuts the stretch at most the length inside (`stretch`: world length a unit of depth), so
// the kernels' tails beyond the face add nothing.
double coveredLength(double a, double b, const RayInterval& inBox, double stretch, double weight);
// The same in the float type T, the box's depths as two numbers: coveredLength is its double
// instance, the CPU splatter's per-pixel classification its float one.
template <typename T>
inline T coveredLengthOf(T a, T b, T boxNear, T boxFar, T stretch, T weight) {
  const T nearDepth = std::max(a, boxNear), farDepth = std::min(b, boxFar);
  const T inside = std::max(farDepth - nearDepth, T(0)) * stretch;
  // Uncut: farDepth - nearDepth is b - a, and the weight is kept as it is.
  return (nearDepth > a || farDepth < b) ? std::min(weight, inside) : weight;
}

}  // namespace ewa
