// Pre-integration between slabs (post-classified splatting): the shared table as GPU texels,
// and the per-pixel classification of a pair of slab values that the slab shader mirrors.
#pragma once

#include <glm/vec4.hpp>
#include <vector>

#include "core/preintegration_table.h"

namespace ewa {

// Entries (front, back) row-major, table.size() squared: rgb the segment's colour per unit
// opacity at the table's distance (c / alpha: the colour with its self-attenuation), a its
// mean extinction per world unit. Unlike c and alpha these hold for any segment length, so
// one table serves every pixel's ray length and a slab's partial coverage at silhouettes.
std::vector<glm::vec4> slabPairTexels(const PreintegrationTable& table);

// Premultiplied (r, g, b, alpha) of a ray segment `length` world units long whose normalized
// value (0 = the table's lo, 1 = hi) runs from `front` to `back`: the texels read with
// bilinear filtering at texel centres, as a GL_LINEAR texture lookup does, then
// alpha = 1 - exp(-length * meanExtinction), colour = rgb * alpha (slab_composite.frag.glsl).
glm::dvec4 classifySlabPair(const std::vector<glm::vec4>& texels, int size, double front,
                            double back, double length);

}  // namespace ewa
