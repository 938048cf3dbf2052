// tileEwaFrame: the splat renderer's pre-classified frame as the compute tile splatter takes it.
#pragma once

#include <glm/vec4.hpp>
#include <vector>

#include "core/camera.h"
#include "core/image8.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "render/renderer.h"
#include "render/splat_renderer.h"
#include "render/tile_ewa_splatter.h"

namespace ewa {

// Every visible splat of `renderer`'s last classification (pre-classified: colour and
// extinction from `tf`), its footprint from the C++ EWA math, and the slab entries a
// SlabPartition built as the renderer builds its own (same thickness, reach and cull), so
// TileEwaSplatter draws the frame the renderer draws from `camera` at width x height.
TileEwaFrame tileEwaFrame(const SplatRenderer& renderer, const Volume& volume,
                          const TransferFunction& tf, const Camera& camera,
                          const RenderSettings& settings, int width, int height);

// TileEwaSplatter's picture (premultiplied, rows bottom up) over `background` as the final
// pass draws it: 8-bit RGB, rows top down, as renderers read theirs back.
Image8 tileEwaImage(const std::vector<glm::vec4>& picture, int width, int height,
                    const glm::dvec3& background);

}  // namespace ewa
