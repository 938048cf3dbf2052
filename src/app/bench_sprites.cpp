// spriteSizes: the splat renderer's footprints, computed on the CPU as its shaders do.
#include "app/bench_sprites.h"

#include <algorithm>

#include "core/ewa_footprint.h"
#include "core/volume_orientation.h"

namespace ewa {

std::vector<glm::vec3> spriteSizes(const SplatRenderer& r, const Volume& vol, const Camera& cam,
                                   const RenderSettings& s, int w, int h) {
  const Projection proj = cam.projection(w, h);
  // Splats sit in the volume's own frame, seen by the camera moved as the renderer moves it.
  const Camera local = cameraInVolumeFrame(cam, vol);
  const glm::dmat4 view = local.viewMatrix();
  const glm::dmat3 cov =
      cameraCovariance(local.rotation(), kernelSigma(vol.spacing(), s.kernelWidth));
  const FootprintParams params = footprintParams(s, vol.spacing());
  std::vector<glm::vec3> out;
  for (const PackedSplat& p : r.splats().splats()) {
    const glm::dvec3 at = vol.framePosition(SplatSet::i(p), SplatSet::j(p), SplatSet::k(p));
    const glm::dvec3 u(view * glm::dvec4(at, 1.0));
    const Footprint fp = computeFootprint(u, cov, proj, params);
    if (!fp.visible) continue;
    const double size = std::min<double>(pointSpriteSize(fp, s.cutoff), r.pointSizeLimit());
    out.emplace_back(float(fp.center.x), float(fp.center.y), float(size));
  }
  return out;
}

}  // namespace ewa
