// Clip uniforms: world-space half-spaces moved into the splat renderer's camera space.
#include "render/clip_uniforms.h"

#include <glm/vec4.hpp>
#include <string>

#include "core/clip_share.h"

namespace ewa {

void setClipUniforms(gl::Program& p, const ClipRegion& region, const Volume& volume,
                     const Camera& volumeCamera, const Projection& proj) {
  const std::vector<HalfSpace> frame = halfSpacesInVolumeFrame(region, volume);
  const glm::dmat4 view = volumeCamera.viewMatrix();
  int count = 0;
  for (const HalfSpace& h : frame) {
    if (count == int(ClipRegion::kMaxHalfSpaces)) break;
    const HalfSpace c = transformed(h, view);
    p.setVec4("uClipPlanes[" + std::to_string(count) + "]",
              glm::vec4(glm::vec3(c.normal), float(c.offset)));
    ++count;
  }
  p.setInt("uClipCount", count);
  const double scale = proj.orthographic ? 1.0 / proj.pixelsPerUnit : 1.0 / proj.focalPixels;
  p.setVec4("uClipRay", glm::vec4(proj.orthographic ? 1.0f : 0.0f, float(scale),
                                  float(proj.principal.x), float(proj.principal.y)));
}

}  // namespace ewa
