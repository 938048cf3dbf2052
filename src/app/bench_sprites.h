// spriteSizes: the bare point sprites the benchmarks draw beside EWA splats, one per splat.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "core/camera.h"
#include "core/volume.h"
#include "render/renderer.h"
#include "render/splat_renderer.h"

namespace ewa {

// Every visible splat's pixel centre and point size (x, y, size) from the C++ footprint, for
// SpriteBaseline: the same number and sizes of points the splat renderer draws from `camera`.
std::vector<glm::vec3> spriteSizes(const SplatRenderer& renderer, const Volume& volume,
                                   const Camera& camera, const RenderSettings& settings, int width,
                                   int height);

}  // namespace ewa
