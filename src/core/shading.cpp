// Phong shading with a head light (see shading.h).
#include "core/shading.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace ewa {

glm::dvec3 headlightShade(const glm::dvec3& rgb, const glm::dvec3& normal, const glm::dvec3& toEye,
                          const Lighting& light) {
  if (!light.enabled || !(glm::dot(normal, normal) > 0.0)) return rgb;
  const double ndl = std::abs(glm::dot(normal, toEye));
  return rgb * (light.ambient + light.diffuse * ndl) +
         glm::dvec3(light.specular * std::pow(ndl, light.shininess));
}

}  // namespace ewa
