// downsampleVolume: a coarser level of detail of a volume, box-averaged, for interaction.
#pragma once

#include "core/volume.h"

namespace ewa {

// Averages blocks of factor^3 voxels into one float32 voxel. Along an axis with fewer voxels
// than `factor` that axis is kept as is. Odd sizes: the last block along an axis holds the
// voxels that remain, and its value is their mean. Spacing grows by the factor actually used
// per axis (so EWA kernels, whose width follows the spacing, grow with it) and the origin moves
// to the centre of the first block, so the coarse volume covers the same world box. NaN voxels
// are left out of their block's mean (a block of only NaN stays NaN). Throws
// std::invalid_argument for factor < 1 or an empty volume.
Volume downsampleVolume(const Volume& volume, int factor);

// Per-axis factor downsampleVolume uses: min(factor, dims[axis]).
int downsampleAxisFactor(int64_t dim, int factor);

}  // namespace ewa
