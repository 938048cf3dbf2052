// The crop box and clipping planes as uniforms of the splat programs (shaders/clip_region.glsl).
#pragma once

#include <glm/mat4x4.hpp>

#include "core/camera.h"
#include "core/clip_region.h"
#include "core/volume.h"
#include "gl/program.h"

namespace ewa {

// Sets uClipPlanes (the region's half-spaces in the camera space of `volumeCamera`, the camera
// that looks at `volume` in its own frame), uClipCount and uPixelRay (pixel rays of `proj`).
// An inactive region sets uClipCount 0: the shaders then clip nothing. `outward`: each
// half-space moved that far away from what it keeps (world units).
void setClipUniforms(gl::Program& program, const ClipRegion& region, const Volume& volume,
                     const Camera& volumeCamera, const Projection& proj, double outward = 0.0);

// Sets the uniforms of shaders/covered_length.glsl: the rays of `proj`'s pixels, the camera
// space of `volumeCamera` to voxel index coordinates and the data's box
// (Volume::indexDataBox), or `indexBox` (index coordinates) in its place.
void setDataBoxUniforms(gl::Program& program, const Volume& volume, const Camera& volumeCamera,
                        const Projection& proj);
void setDataBoxUniforms(gl::Program& program, const Volume& volume, const Camera& volumeCamera,
                        const Projection& proj, const DataBox& indexBox);

}  // namespace ewa
