// Orientation: orthonormalizing and un-reflecting directions, and the volume-frame camera.
#include "core/volume_orientation.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace ewa {

bool isOrthonormal(const glm::dmat3& d, double tolerance) {
  for (int a = 0; a < 3; ++a) {
    if (std::fabs(glm::length(d[a]) - 1.0) > tolerance) return false;
    for (int b = a + 1; b < 3; ++b)
      if (std::fabs(glm::dot(d[a], d[b])) > tolerance) return false;
  }
  return true;
}

namespace {

// `v` divided by its largest component, so that lengths and dot products cannot overflow
// (a header's 1e247 squared is not a double); zero if it has no finite largest component.
glm::dvec3 scaledDown(const glm::dvec3& v) {
  const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  return std::isfinite(m) && m > 0.0 ? v / m : glm::dvec3(0.0);
}

}  // namespace

glm::dmat3 orthonormalized(const glm::dmat3& d) {
  const double det = glm::determinant(d);
  if (!std::isfinite(det) || std::fabs(det) < 1e-12) return glm::dmat3(1.0);
  const glm::dvec3 a = scaledDown(d[0]), b = scaledDown(d[1]);
  if (a == glm::dvec3(0.0) || b == glm::dvec3(0.0)) return glm::dmat3(1.0);
  const glm::dvec3 x = glm::normalize(a);
  glm::dvec3 y = b - glm::dot(b, x) * x;
  if (glm::length(y) < 1e-9) return glm::dmat3(1.0);
  // Twice: when b lies nearly along x, one pass leaves y off square by rounding over |y| (1e-10
  // for |y| = 1e-6), so the rotation would come out different when its own columns are fed
  // back (a volume saved and read again); a second pass leaves rounding alone.
  y = glm::normalize(y);
  y = glm::normalize(y - glm::dot(y, x) * x);
  glm::dvec3 z = glm::cross(x, y);
  if (det < 0.0) z = -z;
  const glm::dmat3 r(x, y, z);
  return isOrthonormal(r, 1e-9) ? r : glm::dmat3(1.0);
}

namespace {

// Reverses the order of the z slices of the grid in place.
void flipSlices(OrientedGrid& g) {
  const size_t slice = size_t(g.dims[0]) * size_t(g.dims[1]) * g.elementSize;
  std::vector<uint8_t> tmp(slice);
  uint8_t* data = g.bytes->data();
  for (int64_t lo = 0, hi = g.dims[2] - 1; lo < hi; ++lo, --hi) {
    std::memcpy(tmp.data(), data + size_t(lo) * slice, slice);
    std::memcpy(data + size_t(lo) * slice, data + size_t(hi) * slice, slice);
    std::memcpy(data + size_t(hi) * slice, tmp.data(), slice);
  }
}

}  // namespace

std::vector<std::string> makeRotation(OrientedGrid& g) {
  std::vector<std::string> notes;
  const bool sheared = !isOrthonormal(g.direction);
  // Even a direction within rounding of a rotation is made exact (float headers are not).
  g.direction = orthonormalized(g.direction);
  if (sheared) {
    notes.push_back(
        "warning: the direction matrix is not orthonormal (gantry tilt or shear); drawn with "
        "the nearest rotation");
  }
  if (glm::determinant(g.direction) < 0.0) {
    if (g.bytes) flipSlices(g);
    g.origin += g.direction[2] * (g.spacing.z * double(g.dims[2] - 1));
    g.direction[2] = -g.direction[2];
    notes.push_back("the direction is a reflection: slices are stored in reverse order");
  }
  return notes;
}

Camera cameraInVolumeFrame(const Camera& world, const Volume& volume) {
  const glm::dmat3& d = volume.direction();
  if (d == glm::dmat3(1.0)) return world;
  const glm::dmat3 inverse = glm::transpose(d);
  const glm::dvec3& o = volume.origin();
  Camera c = world;
  c.position = o + inverse * (world.position - o);
  c.focalPoint = o + inverse * (world.focalPoint - o);
  c.viewUp = inverse * world.viewUp;
  return c;
}

}  // namespace ewa
