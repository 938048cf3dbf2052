// Ghost voxels from the neighbouring ranks: each rank reads only its own brick, and the voxels
// around it come over MPI from the ranks that own them (no extra chunks read from the file).
#pragma once

#include <mpi.h>

#include <vector>

#include "core/volume.h"
#include "dist/brick_split.h"
#include "io/region_read.h"

namespace ewa::dist {

// The voxels of regions[rank] put together from every rank's brick: `own` holds exactly this
// rank's bricks[rank] (its origin at the brick's first voxel; ignored for an empty brick), each
// rank sends every other the part of its brick inside that rank's region. The bricks tile the
// whole volume, each region lies inside it and holds its rank's brick (empty bricks: any
// region, nothing sent or received). Returns the region as a volume like `own` (type, spacing,
// direction, unit, notes and source files), its origin at the region's first voxel; an empty
// volume for an empty brick. Collective over `comm`, whose size is bricks.size(). Throws
// std::invalid_argument when `own` is not its brick's size or a message would pass 2 GiB.
Volume exchangeGhosts(const Volume& own, const std::vector<VoxelBox>& bricks,
                      const std::vector<VoxelRegion>& regions, MPI_Comm comm);

}  // namespace ewa::dist
