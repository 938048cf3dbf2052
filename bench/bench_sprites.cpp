// spriteSizes, tileFootprints: the splat renderer's footprints, computed on the CPU as its shaders
// do.
#include "bench/bench_sprites.h"

#include <algorithm>
#include <cmath>

#include "core/ewa_footprint.h"

namespace ewa {

std::vector<glm::vec3> spriteSizes(const SplatRenderer& r, const Volume& vol, const Camera& cam,
                                   const RenderSettings& s, int w, int h) {
  std::vector<glm::vec3> out;
  forEachFootprint(r, vol, cam, s, w, h, [&](const Footprint& fp, size_t) {
    const double size = std::min<double>(pointSpriteSize(fp, s.cutoff), r.pointSizeLimit());
    out.emplace_back(float(fp.center.x), float(fp.center.y), float(size));
  });
  return out;
}

std::vector<TileFootprint> tileFootprints(const SplatRenderer& r, const Volume& vol,
                                          const Camera& cam, const RenderSettings& s, int w,
                                          int h) {
  std::vector<TileFootprint> out;
  forEachFootprint(r, vol, cam, s, w, h, [&](const Footprint& fp, size_t) {
    // The ellipse r <= cutoff lies within sqrt(cutoff * variance) of the centre on each axis.
    const glm::dvec2 half(std::sqrt(s.cutoff * fp.covariance[0][0]),
                          std::sqrt(s.cutoff * fp.covariance[1][1]));
    out.push_back({glm::vec4(glm::dvec4(fp.center, half)),
                   glm::vec4(glm::dvec4(fp.conic[0][0], fp.conic[0][1], fp.conic[1][1], fp.peak))});
  });
  return out;
}

}  // namespace ewa
