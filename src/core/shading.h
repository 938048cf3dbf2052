// Phong shading with a head light, per splat: the C++ reference of shaders/splat_common.glsl.
#pragma once

#include <glm/vec3.hpp>

namespace ewa {

struct Lighting {
  bool enabled = false;
  double ambient = 0.3;
  double diffuse = 0.7;
  double specular = 0.25;
  double shininess = 24.0;
  bool operator==(const Lighting& o) const {
    return enabled == o.enabled && ambient == o.ambient && diffuse == o.diffuse &&
           specular == o.specular && shininess == o.shininess;
  }
};

// Emitted colour of a splat of transfer-function colour `rgb` with unit camera-space normal
// `normal` (zero: unshaded) lit from the eye along unit `toEye`. Two-sided, because a
// gradient's sign says which side is denser, not which side faces the viewer. With the light at
// the eye the half vector is toEye, so the specular term is |n.l|^shininess, in white.
glm::dvec3 headlightShade(const glm::dvec3& rgb, const glm::dvec3& normal, const glm::dvec3& toEye,
                          const Lighting& light);

}  // namespace ewa
