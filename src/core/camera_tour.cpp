// Camera tours: legs between stops, eased, with the orientation slerped.
#include "core/camera_tour.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <stdexcept>

namespace ewa {

namespace {

// The camera between two, `s` of the way (0: a, 1: b).
Camera between(const Camera& a, const Camera& b, double s) {
  // World-to-camera rotations as quaternions: the shortest turn from one to the other.
  const glm::dquat qa = glm::quat_cast(a.rotation()), qb = glm::quat_cast(b.rotation());
  const glm::dmat3 r = glm::mat3_cast(glm::slerp(qa, qb, s));
  const glm::dmat3 toWorld = glm::transpose(r);
  Camera c;
  c.focalPoint = glm::mix(a.focalPoint, b.focalPoint, s);
  const double distance = std::exp(glm::mix(std::log(a.distance()), std::log(b.distance()), s));
  // The camera looks down its -z, with +y up.
  c.position = c.focalPoint - toWorld * glm::dvec3(0.0, 0.0, -1.0) * distance;
  c.viewUp = toWorld * glm::dvec3(0.0, 1.0, 0.0);
  c.viewAngleDeg = glm::mix(a.viewAngleDeg, b.viewAngleDeg, s);
  c.orthographic = s < 0.5 ? a.orthographic : b.orthographic;
  return c;
}

ClipRegion between(const ClipRegion& a, const ClipRegion& b, double s) {
  ClipRegion c = s < 0.5 ? a : b;
  if (a.cropEnabled && b.cropEnabled) {
    c.cropMin = glm::mix(a.cropMin, b.cropMin, s);
    c.cropMax = glm::mix(a.cropMax, b.cropMax, s);
  }
  return c;
}

}  // namespace

TourStop tourStop(const std::vector<TourStop>& stops, double t) {
  if (stops.empty()) throw std::invalid_argument("a tour needs at least one stop");
  if (stops.size() == 1) return stops.front();
  const double legs = double(stops.size() - 1);
  const double at = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * legs;
  const size_t leg = std::min(size_t(at), stops.size() - 2);
  const double u = at - double(leg);
  const double s = u * u * (3.0 - 2.0 * u);  // smoothstep: at rest at both stops
  const TourStop& a = stops[leg];
  const TourStop& b = stops[leg + 1];
  return {between(a.camera, b.camera, s), between(a.clip, b.clip, s)};
}

TourStop tourFrame(const std::vector<TourStop>& stops, int index, int count) {
  return tourStop(stops, count > 1 ? double(index) / double(count - 1) : 0.0);
}

}  // namespace ewa
