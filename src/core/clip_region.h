// ClipRegion: the crop box and clipping planes that limit what of a volume is drawn (world space).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace ewa {

// The half-space dot(normal, x) + offset >= 0 (the side the normal points into is kept).
struct HalfSpace {
  glm::dvec3 normal{0.0, 0.0, 1.0};
  double offset = 0.0;

  double distance(const glm::dvec3& x) const;  // signed; >= 0 inside (normal of unit length)
};

// The half-space moved by a rigid map x -> R x + t (rotation and translation only).
HalfSpace transformed(const HalfSpace& h, const glm::dmat4& rigid);

// A clipping plane through `point` keeping the side `normal` points into (VTK's clipping
// planes); `enabled` lets the window keep a plane switched off.
struct ClipPlane {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};
  bool enabled = true;
};

// Depths (or ray parameters) [near, far] kept along one ray; empty when near > far.
struct RayInterval {
  double near = -1e300;
  double far = 1e300;
  bool empty() const { return near > far; }
};

struct ClipRegion {
  static constexpr size_t kMaxPlanes = 6;
  // Uniform arrays in shaders/clip_region.glsl hold this many half-spaces: box + planes.
  static constexpr size_t kMaxHalfSpaces = 6 + kMaxPlanes;

  bool cropEnabled = false;
  glm::dvec3 cropMin{0.0}, cropMax{0.0};  // the kept box (VTK's cropping region planes)
  std::vector<ClipPlane> planes;          // at most kMaxPlanes

  // True when anything is clipped away: the renderers skip all clipping otherwise.
  bool active() const;
  // The region as unit-normal half-spaces in world space: the six faces of the box (when
  // enabled) and every enabled plane with a non-zero normal.
  std::vector<HalfSpace> halfSpaces() const;
  bool contains(const glm::dvec3& world) const;
  // The part of the ray origin + t * direction, t in [tMin, tMax], inside the region.
  RayInterval clipRay(const glm::dvec3& origin, const glm::dvec3& direction, double tMin = -1e300,
                      double tMax = 1e300) const;
  bool operator==(const ClipRegion& o) const;
  bool operator!=(const ClipRegion& o) const { return !(*this == o); }
};

bool operator==(const ClipPlane& a, const ClipPlane& b);

// The interval of t where a half-space keeps origin + t * direction, intersected into `span`.
void clipRayBy(const HalfSpace& h, const glm::dvec3& origin, const glm::dvec3& direction,
               RayInterval* span);

// "X0,X1,Y0,Y1,Z0,Z1" (--crop): a box with X0 < X1 etc. Returns "" or a one-line problem.
std::string parseCropBox(const std::string& text, ClipRegion* region);
// "PX,PY,PZ,NX,NY,NZ" (--clip-plane): appended to region->planes; the normal must not be zero
// and at most kMaxPlanes planes are taken. Returns "" or a one-line problem.
std::string parseClipPlane(const std::string& text, ClipRegion* region);

}  // namespace ewa
