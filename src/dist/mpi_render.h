// Distributed headless rendering: every rank draws its brick of the volume cut exactly at the
// brick's faces, IceT blends the pictures in visibility order, rank 0 writes the file.
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

#include "app/options.h"
#include "core/image8.h"
#include "render/renderer.h"

namespace ewa::dist {

// Why these options cannot be drawn by ewaview-mpi (one line), or "" when they can: one picture
// (--output) of one channel by the splat renderer.
std::string distributedUsageProblem(const Options& options);

// The picture the splat renderer's final pass makes of `picture` (readFramePicture: bottom row
// first) under `settings` (mode, background, X-ray map and scale), top row first, 8-bit RGB:
// shaders/final_composite.frag.glsl on the CPU.
Image8 finishPicture(const std::vector<float>& picture, int width, int height,
                     const RenderSettings& settings);

// What one distributed render did, for --stats: per rank, and the composite.
struct DistributedStats {
  std::vector<double> renderMs;   // each rank's frame (rank order)
  std::vector<long long> voxels;  // each rank's brick's voxels
  double compositeMs = 0.0;       // IceT's blend or the reduction, on rank 0
};

// Loads the scene on every rank, checks that the ranks agree on it, splits the voxel box into
// one brick per rank of `comm`, renders this rank's brick and composites; rank 0 writes
// options.output. Returns the exit status (0, or 1 after one line on stderr from one rank),
// the same on every rank. Collective; an error after the ranks have agreed to go on (a
// composite failing on one rank) ends every rank through MPI_Abort after its line.
int renderDistributed(const Options& options, MPI_Comm comm);

}  // namespace ewa::dist
