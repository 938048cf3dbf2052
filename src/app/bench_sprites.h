// spriteSizes, tileFootprints: the bare point sprites and compute-tile footprints the
// benchmarks draw beside EWA splats, one per splat.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "core/camera.h"
#include "core/volume.h"
#include "render/renderer.h"
#include "render/splat_renderer.h"
#include "render/tile_splat_baseline.h"

namespace ewa {

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
