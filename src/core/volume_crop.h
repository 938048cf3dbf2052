// Cutting a volume down to the voxels a world-space box keeps (--crop with --save-volume, the
// window's "only the crop box" when saving).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>

#include "core/volume.h"

namespace ewa {

// Voxel index ranges, inclusive at both ends.
struct VoxelRange {
  std::array<int64_t, 3> low{0, 0, 0};
  std::array<int64_t, 3> high{0, 0, 0};
  std::array<int64_t, 3> dims() const {
    return {high[0] - low[0] + 1, high[1] - low[1] + 1, high[2] - low[2] + 1};
  }
};

// The voxels whose centres lie in the world-space box [boxMin, boxMax] (Volume::worldPosition):
// for a grid turned against the world's axes, the index range holding every such centre (a
// grid cannot be cut along another grid's planes). Nothing when no centre lies inside.
std::optional<VoxelRange> voxelsInBox(const Volume& volume, const glm::dvec3& boxMin,
                                      const glm::dvec3& boxMax);

// The voxels of `range` as a volume of their own, where they were in world space (the origin
// moved to the first), with the spacing, direction, unit and notes, and a note naming the range.
// Throws std::invalid_argument for a range outside the volume.
Volume cropVolume(const Volume& volume, const VoxelRange& range);

}  // namespace ewa
