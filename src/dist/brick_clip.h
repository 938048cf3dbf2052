// A brick as the renderer's clip region: its faces inside the volume as clipping planes, so the
// crop machinery keeps the kernels of voxels outside that reach in and cuts them exactly.
#pragma once

#include <string>

#include "core/clip_region.h"
#include "core/volume.h"
#include "dist/brick_split.h"

namespace ewa::dist {

// `clip` (the user's crop box and planes) with a plane for each face of `brick` that lies inside
// the volume, at index coordinate low - 0.5 or high - 0.5, keeping the brick's side (world
// space; any spacing and direction). Faces on the volume's own boundary are not cut, so the
// bricks' regions tile the whole volume's. Returns "" or, when the planes would exceed
// ClipRegion::kMaxPlanes, a one-line problem.
std::string addBrickPlanes(const Volume& volume, const VoxelBox& brick, ClipRegion* clip);

}  // namespace ewa::dist
