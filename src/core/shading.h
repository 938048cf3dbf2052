// Phong shading with a head light, per splat: the C++ reference of shaders/splat_common.glsl.
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
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

// The head light at unit normal `normal` (zero: unlit) seen along unit `toEye`, as a gain on the
// colour and a white term: the shaded colour is rgb * gain + white, so a premultiplied colour
// shades as rgb * gain + white * alpha. Two-sided, because a gradient's sign says which side is
// denser, not which side faces the viewer. With the light at the eye the half vector is toEye,
// so the specular term is |n.l|^shininess. In the float type T: headlightShade takes it in
// double, the CPU splatter's per-pixel shading in float.
template <typename T>
struct HeadlightTerms {
  T gain = T(1);
  T white = T(0);
};
template <typename T>
inline HeadlightTerms<T> headlightTermsOf(const glm::vec<3, T>& normal, const glm::vec<3, T>& toEye,
                                          const Lighting& light) {
  if (!light.enabled || !(glm::dot(normal, normal) > T(0))) return {};
  const T ndl = std::abs(glm::dot(normal, toEye));
  return {T(light.ambient) + T(light.diffuse) * ndl,
          T(light.specular) * std::pow(ndl, T(light.shininess))};
}

// Emitted colour of a splat of transfer-function colour `rgb` with unit camera-space normal
// `normal` (zero: unshaded) lit from the eye along unit `toEye` (headlightTermsOf).
glm::dvec3 headlightShade(const glm::dvec3& rgb, const glm::dvec3& normal, const glm::dvec3& toEye,
                          const Lighting& light);

}  // namespace ewa
