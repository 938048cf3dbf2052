// Clip uniforms: world-space half-spaces moved into the splat renderer's camera space.
#include "render/clip_uniforms.h"

#include <glm/vec4.hpp>
#include <string>

#include "core/clip_share.h"
#include "core/covered_length.h"

namespace ewa {

namespace {

// shaders/pixel_ray.glsl's uPixelRay: (1 orthographic / 0 perspective, 1 / (ppu or focal
// pixels), principal point).
void setPixelRays(gl::Program& p, const Projection& proj) {
  const double scale = proj.orthographic ? 1.0 / proj.pixelsPerUnit : 1.0 / proj.focalPixels;
  p.setVec4("uPixelRay", glm::vec4(proj.orthographic ? 1.0f : 0.0f, float(scale),
                                   float(proj.principal.x), float(proj.principal.y)));
}

}  // namespace

void setClipUniforms(gl::Program& p, const ClipRegion& region, const Volume& volume,
                     const Camera& volumeCamera, const Projection& proj, double outward) {
  const std::vector<HalfSpace> frame = halfSpacesInVolumeFrame(region, volume);
  const glm::dmat4 view = volumeCamera.viewMatrix();
  int count = 0;
  for (const HalfSpace& h : frame) {
    if (count == int(ClipRegion::kMaxHalfSpaces)) break;
    const HalfSpace c = transformed(h, view);
    p.setVec4("uClipPlanes[" + std::to_string(count) + "]",
              glm::vec4(glm::vec3(c.normal), float(c.offset + outward)));
    ++count;
  }
  p.setInt("uClipCount", count);
  setPixelRays(p, proj);
}

void setDataBoxUniforms(gl::Program& p, const Volume& volume, const Camera& volumeCamera,
                        const Projection& proj) {
  setDataBoxUniforms(p, volume, volumeCamera, proj, volume.indexDataBox());
}

void setDataBoxUniforms(gl::Program& p, const Volume& volume, const Camera& volumeCamera,
                        const Projection& proj, const DataBox& indexBox) {
  p.setMat4("uCameraToIndex", glm::mat4(cameraToIndex(volume, volumeCamera)));
  p.setVec3("uBoxLow", glm::vec3(indexBox.low));
  p.setVec3("uBoxHigh", glm::vec3(indexBox.high));
  setPixelRays(p, proj);
}

}  // namespace ewa
