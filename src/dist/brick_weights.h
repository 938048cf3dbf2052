// The visible voxels per block of the whole volume: the weights a split balanced by what the
// ranks draw (VoxelWeights' block weights) takes, counted brick by brick.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/splat_attributes.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "dist/brick_split.h"

namespace ewa::dist {

// The block edge of the visible-voxel weights, in voxels: coarse enough that the weights of a
// large volume are cheap to sum over the ranks, fine enough to cut close to empty space.
constexpr int64_t kVisibleBlock = 8;

// One weight per block of `block` voxels a side of a whole volume of `dims` voxels (x fastest,
// as VoxelWeights takes them): how many voxels of `brick` (whole-volume indices) become splats
// under `tf`, counted in `volume`, which holds the whole's voxels from `offset` on (its voxel
// (0,0,0) is the whole's `offset`) with the ghosts around the brick, and the whole's value range.
// Pre-classified: voxels whose opacity is above 0 (on a table over the value range, as
// classification looks it up). Post-classified: the voxels postClassificationMask keeps (the
// visible ones, those beside a crossing and the margin around them), the margin read from the
// ghosts. Blocks outside the brick weigh 0, so the sum over the bricks is the whole volume's.
// A surface criterion is not applied (it keeps a subset). Throws std::invalid_argument when
// `brick` does not lie in `volume`.
std::vector<double> visibleBlockWeights(const Volume& volume, const std::array<int64_t, 3>& offset,
                                        const VoxelBox& brick, const std::array<int64_t, 3>& dims,
                                        int64_t block, const TransferFunction& tf,
                                        const Classification& classification);

// What a voxel that is not drawn weighs against one that is (addVoxelWeights): it is still read,
// held and classified. It also bounds a brick of empty space: a brick holds at most (1 + f / k)
// times an even share of the voxels, f the visible fraction, so a rank's memory stays near the
// split by voxels where little is visible.
constexpr double kHiddenVoxelWeight = 0.125;

// Adds `perVoxel` times each block's voxel count to `weights` (one per block of `block` voxels a
// side of `dims`, x fastest, the last blocks cut short by the volume's end). Throws
// std::invalid_argument when `weights` has another size.
void addVoxelWeights(std::vector<double>& weights, const std::array<int64_t, 3>& dims,
                     int64_t block, double perVoxel);

}  // namespace ewa::dist
