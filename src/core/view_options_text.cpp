// viewOptionsText: a camera, picture size and clip region written as the options that read
// them back.
#include "core/view_options_text.h"

#include <cstdio>

namespace ewa {

namespace {

// %.12g: short for round numbers, and far inside 1e-9 of the value for any a view holds.
std::string numbers(std::initializer_list<double> values) {
  std::string out;
  for (const double v : values) {
    char text[32];
    std::snprintf(text, sizeof text, "%.12g", v == 0.0 ? 0.0 : v);  // never "-0"
    if (!out.empty()) out += ',';
    out += text;
  }
  return out;
}

std::string vec(const glm::dvec3& v) {
  return numbers({v.x, v.y, v.z});
}

}  // namespace

std::string viewOptionsText(const Camera& camera, glm::ivec2 size, const ClipRegion& clip) {
  std::string out = "--camera-position=" + vec(camera.position) +
                    " --camera-focal-point=" + vec(camera.focalPoint) +
                    " --camera-view-up=" + vec(camera.viewUp) +
                    " --camera-view-angle=" + numbers({camera.viewAngleDeg});
  if (camera.orthographic) out += " --camera-orthographic";
  out += " --resolution=" + std::to_string(size.x) + "," + std::to_string(size.y);
  if (clip.cropEnabled)
    out += " --crop=" + numbers({clip.cropMin.x, clip.cropMax.x, clip.cropMin.y, clip.cropMax.y,
                                 clip.cropMin.z, clip.cropMax.z});
  for (const ClipPlane& p : clip.planes)
    if (p.enabled) out += " --clip-plane=" + vec(p.point) + "," + vec(p.normal);
  return out;
}

}  // namespace ewa
