// Camera: position, focal point, view-up and view angle, as f3d and VTK define them.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ewa {

// How camera space maps to pixels: what the EWA footprint needs from the camera.
struct Projection {
  bool orthographic = false;
  double focalPixels = 1.0;    // perspective: pixels per unit of (lateral / depth)
  double pixelsPerUnit = 1.0;  // orthographic: pixels per world unit
  glm::dvec2 principal{0.0};   // pixel coordinates of the view axis
  int width = 1;
  int height = 1;
};

class Camera {
 public:
  glm::dvec3 position{0.0, 0.0, 1.0};
  glm::dvec3 focalPoint{0.0};
  glm::dvec3 viewUp{0.0, 1.0, 0.0};
  double viewAngleDeg = 30.0;  // vertical
  bool orthographic = false;

  // World to camera space (OpenGL convention: the camera looks down -z, y is up).
  glm::dmat4 viewMatrix() const;
  // The rotation part of viewMatrix (W in the EWA paper).
  glm::dmat3 rotation() const;
  // Unit vector from the position towards the focal point.
  glm::dvec3 direction() const;
  double distance() const;
  // Pixel mapping for a width x height image. Orthographic views show the height the
  // perspective view shows at the focal point: 2 * distance * tan(angle / 2).
  Projection projection(int width, int height) const;

  // Points the camera at the center of [lo, hi] from `fromDirection` (pointing from the focal
  // point to the eye), far enough that the bounding sphere fills the view's height.
  void frame(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& fromDirection,
             const glm::dvec3& up, double aspect);
  // Rotates the eye about the focal point: azimuth about view-up, elevation about the right axis.
  void orbit(double azimuthDeg, double elevationDeg);
  // Moves the eye towards the focal point by `factor` (> 1 moves closer).
  void dolly(double factor);
  // Moves eye and focal point across the view by (dx, dy) in world units.
  void pan(double dx, double dy);

  // True when position, focal point and view-up define a valid view.
  bool valid() const;
};

}  // namespace ewa
