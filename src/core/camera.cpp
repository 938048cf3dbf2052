// Camera: view matrix, pixel projection and the orbit/dolly/pan motions.
#include "core/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace ewa {

namespace {
constexpr double kPi = 3.14159265358979323846;
double radians(double deg) {
  return deg * kPi / 180.0;
}

// An up vector that is not parallel to `dir`.
glm::dvec3 safeUp(const glm::dvec3& dir, const glm::dvec3& up) {
  if (glm::length(glm::cross(dir, up)) > 1e-9 * glm::length(up)) return up;
  return std::abs(dir.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
}
}  // namespace

glm::dmat4 Camera::viewMatrix() const {
  return glm::lookAt(position, focalPoint, safeUp(direction(), viewUp));
}

glm::dmat3 Camera::rotation() const {
  return glm::dmat3(viewMatrix());
}

glm::dvec3 Camera::direction() const {
  return glm::normalize(focalPoint - position);
}

double Camera::distance() const {
  return glm::length(focalPoint - position);
}

Projection Camera::projection(int width, int height) const {
  Projection p;
  p.orthographic = orthographic;
  p.width = width;
  p.height = height;
  p.principal = glm::dvec2(width * 0.5, height * 0.5);
  const double halfTan = std::tan(radians(viewAngleDeg) * 0.5);
  p.focalPixels = (height * 0.5) / halfTan;
  p.pixelsPerUnit = height / (2.0 * distance() * halfTan);
  return p;
}

void Camera::frame(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& fromDirection,
                   const glm::dvec3& up, double aspect) {
  focalPoint = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-6);
  // The narrower of the two view angles must hold the sphere.
  double half = radians(viewAngleDeg) * 0.5;
  if (aspect < 1.0) half = std::atan(std::tan(half) * aspect);
  const double dist = radius / std::sin(half);
  position = focalPoint + glm::normalize(fromDirection) * dist;
  viewUp = safeUp(-fromDirection, up);
}

void Camera::orbit(double azimuthDeg, double elevationDeg) {
  glm::dvec3 up = glm::normalize(safeUp(direction(), viewUp));
  glm::dvec3 offset = position - focalPoint;
  offset = glm::dmat3(glm::rotate(glm::dmat4(1.0), radians(azimuthDeg), up)) * offset;
  const glm::dvec3 right = glm::normalize(glm::cross(-offset, up));
  const glm::dmat3 tilt(glm::rotate(glm::dmat4(1.0), radians(elevationDeg), right));
  offset = tilt * offset;
  // Keep view-up orthogonal to the view direction so elevation can pass over the pole.
  viewUp = glm::normalize(tilt * up);
  position = focalPoint + offset;
}

void Camera::dolly(double factor) {
  if (!(factor > 0.0)) return;
  position = focalPoint + (position - focalPoint) / factor;
}

void Camera::pan(double dx, double dy) {
  const glm::dvec3 dir = direction();
  const glm::dvec3 right = glm::normalize(glm::cross(dir, safeUp(dir, viewUp)));
  const glm::dvec3 up = glm::cross(right, dir);
  const glm::dvec3 move = right * dx + up * dy;
  position += move;
  focalPoint += move;
}

bool Camera::valid() const {
  const glm::dvec3 d = focalPoint - position;
  const double len = glm::length(d);
  return std::isfinite(len) && len > 0.0 && glm::length(viewUp) > 0.0 &&
         std::isfinite(viewAngleDeg) && viewAngleDeg > 0.0 && viewAngleDeg < 180.0;
}

}  // namespace ewa
