// Clipped shares of splat kernels: the part of a kernel's 1D Gaussian along a pixel's ray that
// lies on the kept side of the clip region. Mirrored line for line in shaders/clip_region.glsl.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "core/camera.h"
#include "core/clip_region.h"
#include "core/ewa_footprint.h"
#include "core/volume.h"

namespace ewa {

// Stands for an unbounded depth in the shaders (float): far beyond any scene, and safe to
// subtract and scale without overflow.
constexpr double kClipUnbounded = 1e30;

// The rigid map from world space to the volume's own frame (origin + (i,j,k) * spacing, no
// direction), where the splat and shear-warp renderers work (see cameraInVolumeFrame).
glm::dmat4 worldToVolumeFrame(const Volume& volume);
// The region's half-spaces in the volume's own frame.
std::vector<HalfSpace> halfSpacesInVolumeFrame(const ClipRegion& region, const Volume& volume);
// The bounds of the convex polytope that the half-spaces `cuts` leave of `box` (its corners:
// where three planes, the box's faces among them, meet inside all the others); none when
// nothing is left.
std::optional<DataBox> polytopeBounds(const DataBox& box, const std::vector<HalfSpace>& cuts);
// The volume's box in its own frame grown by `grow` on every side (how far kernels reach out of
// it), narrowed to what the crop box and clipping planes, each moved `outward` away from what it
// keeps, leave of it (polytopeBounds, a hair wider for rounding), which the clip cuts every ray
// at: a box holding all that is drawn. The grown box when nothing is clipped or nothing is left.
DataBox keptBoxInVolumeFrame(const ClipRegion& region, const Volume& volume, double grow = 0.0,
                             double outward = 0.0);

// The depths [near, far] that camera-space half-spaces keep along the ray through `pixel` (the
// splat shaders' pixel frame: gl_FragCoord, principal point at the image centre). Depth is
// -z in camera space, the coordinate the footprint's depth Gaussian and the slabs use.
// Without half-spaces: [-kClipUnbounded, kClipUnbounded]; empty when nothing is kept.
RayInterval clippedDepths(const std::vector<HalfSpace>& cameraPlanes, const Projection& proj,
                          const glm::dvec2& pixel);

// The depths a slab share integrates between: [zNear, zFar] inside `kept`, an open bound
// (the kernel's tail) the kept one; empty where nothing is left (clippedSlabFraction's bounds,
// which the CPU splatter takes once a kernel and pixel).
RayInterval slabShareBounds(double zNear, double zFar, bool openNear, bool openFar,
                            const RayInterval& kept);

// The share of a depth Gaussian (mean mu, deviation sigma) between zNear and zFar (an open
// bound: the kernel's tail, as slabFraction's infinities) and inside `kept`: the slab split
// and the clip cut in one erf difference, so a kernel straddling a plane gives only its part
// on the kept side.
double clippedSlabFraction(double mu, double sigma, double zNear, double zFar, bool openNear,
                           bool openFar, const RayInterval& kept, const DepthProfile& profile = {});

// True when a kernel centred at camera-space `u` lies more than `reach` outside one of the
// half-spaces: none of it is kept, so it is not drawn.
bool clipCullsKernel(const std::vector<HalfSpace>& cameraPlanes, const glm::dvec3& u, double reach);

}  // namespace ewa
