// spriteSizes, tileFootprints: the splat renderer's footprints, computed on the CPU as its shaders
// do.
#include "app/bench_sprites.h"

#include <algorithm>
#include <cmath>

#include "core/ewa_footprint.h"
#include "core/volume_orientation.h"

namespace ewa {

namespace {

// Calls `visit` with every visible splat's footprint, computed as the splat shaders do.
template <typename Visit>
void forEachFootprint(const SplatRenderer& r, const Volume& vol, const Camera& cam,
                      const RenderSettings& s, int w, int h, Visit visit) {
  const Projection proj = cam.projection(w, h);
  // Splats sit in the volume's own frame, seen by the camera moved as the renderer moves it.
  const Camera local = cameraInVolumeFrame(cam, vol);
  const glm::dmat4 view = local.viewMatrix();
  const glm::dmat3 cov =
      cameraCovariance(local.rotation(), kernelSigma(vol.spacing(), s.kernelWidth));
  const FootprintParams params = footprintParams(s, vol.spacing());
  for (const PackedSplat& p : r.splats().splats()) {
    const glm::dvec3 at = vol.framePosition(SplatSet::i(p), SplatSet::j(p), SplatSet::k(p));
    const glm::dvec3 u(view * glm::dvec4(at, 1.0));
    const Footprint fp = computeFootprint(u, cov, proj, params);
    if (fp.visible) visit(fp);
  }
}

}  // namespace

std::vector<glm::vec3> spriteSizes(const SplatRenderer& r, const Volume& vol, const Camera& cam,
                                   const RenderSettings& s, int w, int h) {
  std::vector<glm::vec3> out;
  forEachFootprint(r, vol, cam, s, w, h, [&](const Footprint& fp) {
    const double size = std::min<double>(pointSpriteSize(fp, s.cutoff), r.pointSizeLimit());
    out.emplace_back(float(fp.center.x), float(fp.center.y), float(size));
  });
  return out;
}

std::vector<TileFootprint> tileFootprints(const SplatRenderer& r, const Volume& vol,
                                          const Camera& cam, const RenderSettings& s, int w,
                                          int h) {
  std::vector<TileFootprint> out;
  forEachFootprint(r, vol, cam, s, w, h, [&](const Footprint& fp) {
    // The ellipse r <= cutoff lies within sqrt(cutoff * variance) of the centre on each axis.
    const glm::dvec2 half(std::sqrt(s.cutoff * fp.covariance[0][0]),
                          std::sqrt(s.cutoff * fp.covariance[1][1]));
    out.push_back({glm::vec4(glm::dvec4(fp.center, half)),
                   glm::vec4(glm::dvec4(fp.conic[0][0], fp.conic[0][1], fp.conic[1][1], fp.peak))});
  });
  return out;
}

}  // namespace ewa
