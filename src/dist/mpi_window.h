// ewaview-mpi without --output: the window on rank 0, every frame drawn by every rank.
#pragma once

#include <mpi.h>

#include "app/options.h"
#include "core/volume.h"

namespace ewa::dist {

class BrickSource;

// Opens the session on every rank of `comm`; rank 0 opens the window over a stand-in of the
// whole volume and sends each frame the window draws to the others, which draw their bricks
// until the window closes. With EWAVIEW_MPI_SCRIPT=FILE in rank 0's environment there is no
// window: each line of FILE, "OUT.png OPTIONS...", is a frame of the command line with OPTIONS
// added (camera, transfer function, crop, size), drawn the window's way and written to OUT.png.
// Returns the exit status, the same on every rank: 0, or 1 after one line.
int runDistributedWindow(const Options& options, int argc, char** argv, MPI_Comm comm);

// Rank 0's stand-in for the whole volume, which the window needs for what it does beside
// drawing (the transfer-function editor's histogram, the crop box's bounds, the probe): the
// whole volume read from the source where it has at most `maxVoxels` voxels, else the volume
// averaged down by the least power of 2 that fits (read a slab of that many z-layers at a time),
// with the whole's world bounds; either way with the value range and histogram of `statistics`
// (a brick carrying the ranks' agreed ones).
Volume standInVolume(BrickSource& source, const Volume& statistics, int64_t maxVoxels);

}  // namespace ewa::dist
