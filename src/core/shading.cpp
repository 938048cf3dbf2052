// Phong shading with a head light (see shading.h).
#include "core/shading.h"

namespace ewa {

glm::dvec3 headlightShade(const glm::dvec3& rgb, const glm::dvec3& normal, const glm::dvec3& toEye,
                          const Lighting& light) {
  const HeadlightTerms<double> t = headlightTermsOf(normal, toEye, light);
  return rgb * t.gain + glm::dvec3(t.white);
}

}  // namespace ewa
