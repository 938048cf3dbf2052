// spriteSizes, tileFootprints: the bare point sprites and compute-tile footprints the
// benchmarks draw beside EWA splats, one per splat.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "bench/tile_splat_baseline.h"
#include "core/camera.h"
#include "core/ewa_footprint.h"
#include "core/volume.h"
#include "core/volume_orientation.h"
#include "render/renderer.h"
#include "render/splat_renderer.h"

namespace ewa {

// Calls visit(footprint, splat index) with every visible splat of `renderer`'s last
// classification, its footprint computed as the splat shaders compute it (C++ EWA math) from
// `camera` at width x height.
template <typename Visit>
void forEachFootprint(const SplatRenderer& renderer, const Volume& volume, const Camera& camera,
                      const RenderSettings& settings, int width, int height, Visit visit) {
  const Projection proj = camera.projection(width, height);
  // Splats sit in the volume's own frame, seen by the camera moved as the renderer moves it.
  const Camera local = cameraInVolumeFrame(camera, volume);
  const glm::dmat4 view = local.viewMatrix();
  const glm::dmat3 cov =
      cameraCovariance(local.rotation(), kernelSigma(volume.spacing(), settings.kernelWidth));
  const FootprintParams params = footprintParams(settings, volume.spacing());
  const auto& splats = renderer.splats().splats();
  for (size_t n = 0; n < splats.size(); ++n) {
    const PackedSplat& p = splats[n];
    const glm::dvec3 at = volume.framePosition(SplatSet::i(p), SplatSet::j(p), SplatSet::k(p));
    const Footprint fp =
        computeFootprint(glm::dvec3(view * glm::dvec4(at, 1.0)), cov, proj, params);
    if (fp.visible) visit(fp, n);
  }
}

// Every visible splat's pixel centre and point size (x, y, size) from the C++ footprint, for
// SpriteBaseline: the same number and sizes of points the splat renderer draws from `camera`.
std::vector<glm::vec3> spriteSizes(const SplatRenderer& renderer, const Volume& volume,
                                   const Camera& camera, const RenderSettings& settings, int width,
                                   int height);

// The same visible splats' footprints for TileSplatBaseline: each one's box, conic and peak.
std::vector<TileFootprint> tileFootprints(const SplatRenderer& renderer, const Volume& volume,
                                          const Camera& camera, const RenderSettings& settings,
                                          int width, int height);

}  // namespace ewa
