// What a brick needs from the whole volume beyond its own voxels: ghost voxels as far as
// anything drawn inside it reads, and one slab grid anchor shared by every brick.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/kernel_reach.h"
#include "core/slab_partition.h"
#include "core/splat_attributes.h"
#include "core/volume.h"

namespace ewa::dist {

// What reaches across a brick's faces in a frame.
struct GhostReach {
  KernelReach reach;  // the frame's (kernelReach: projection, filter, cutoff, kernel width)
  // The farthest camera depth of the whole volume: where pixels are widest and Swan's filter
  // stretches kernels most, so the reach there bounds it everywhere.
  double farDepth = 0.0;
  Classification classification;  // as the splats are built (splatClassification)
  int stride = 1;                 // a level of detail's voxel step
};

// Ghost voxels a brick needs on each side along each axis so that every kernel drawn inside it,
// its classification and its gradient are the whole volume's: the kernel's reach in voxels
// (worldReach at farDepth: the cutoff ellipsoid stretched by Swan's filter plus the low-pass
// pixel, over the axis's spacing; a kernel centred that far outside still draws inside), plus
// what deciding and shading such a kernel reads around it: post-classified, the margin's radius
// (ceil of sqrt(postMarginSquared)) and one voxel more for the crossing test between
// 6-neighbours; else one voxel (the value prefilter's Laplacian, the gradient's central
// differences, the surface test's 6-neighbours). All times the stride.
std::array<int64_t, 3> ghostVoxels(const GhostReach& ghost, const glm::dvec3& spacing);

// The slab grid's anchor (DepthExtent::anchorDepth) for a volume whose data box is `box` (index
// coordinates) in the frame where voxel (i,j,k) sits at origin + (i,j,k) * spacing, seen through
// `view`: the front of a kernel centred at the box's corner nearest the eye. Every process
// computes it from the whole volume alike, so every brick cuts the same slabs.
double slabAnchorDepth(const DataBox& box, const glm::dvec3& origin, const glm::dmat4& view,
                       const DepthExtent& extent);

// The farthest camera depth of the box's corners (GhostReach::farDepth), in the same frame.
double farthestDepth(const DataBox& box, const glm::dvec3& origin, const glm::dvec3& spacing,
                     const glm::dmat4& view);

}  // namespace ewa::dist
