// Distributed headless rendering: every rank draws its brick of the volume cut exactly at the
// brick's faces, IceT blends the pictures in visibility order, rank 0 writes the file.
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

#include "app/options.h"
#include "core/camera.h"
#include "core/image8.h"
#include "core/splat_attributes.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "dist/brick_ghosts.h"
#include "dist/brick_split.h"
#include "dist/mpi_brick_source.h"
#include "render/renderer.h"

namespace ewa::dist {

// Why these options cannot be drawn by ewaview-mpi (one line), or "" when they can: one picture,
// a turntable or a tour (--output), or the window (without it), of one channel by the splat
// renderer.
std::string distributedUsageProblem(const Options& options);

// The picture the splat renderer's final pass makes of `picture` (readFramePicture: bottom row
// first) under `settings` (mode, background, X-ray map and scale), top row first, 8-bit RGB:
// shaders/final_composite.frag.glsl on the CPU.
Image8 finishPicture(const std::vector<float>& picture, int width, int height,
                     const RenderSettings& settings);

// How far a frame's kernels, classification and gradients reach across a brick face of the
// whole volume `grid` (ghostVoxels turns it into voxels): the frame's kernel reach, at the
// whole volume's farthest corner, and its classification.
GhostReach frameGhostReach(const WholeGrid& grid, const Camera& camera,
                           const RenderSettings& settings, int width, int height);

// The slab grid's anchor from the whole data box alone (slabAnchorDepth: the front of a kernel
// at its nearest corner), for `volume` a brick carrying the whole's data box or the whole
// volume: a grid every rank can compute without its splats.
double cornerSlabAnchor(const Volume& volume, const Camera& camera, const RenderSettings& settings,
                        int width, int height);

// The front of the nearest kernel (nearestKernelFront) among `splats` (classifySplats of
// `volume`) whose voxels lie in `brick` (in `volume`'s indices). The least over the bricks is the
// whole volume's nearest kernel's front: where the one-process partition starts its slab grid.
double brickKernelFront(const Volume& volume, const VoxelBox& brick, const SplatSet& splats,
                        const AttributeList& attributes, const Camera& camera,
                        const RenderSettings& settings, int width, int height);
double brickKernelFront(const Volume& volume, const VoxelBox& brick, const ClassifiedSplats& splats,
                        const Camera& camera, const RenderSettings& settings, int width,
                        int height);

// One brick's picture as renderDistributed draws it (readFramePicture: premultiplied RGBA
// floats, bottom row first): `volume` holds the brick `brick` (in its own voxel indices) and
// the ghost voxels around it, and carries the whole volume's value range, histogram and data box
// (Volume::setValueStatistics, setIndexDataBox, in its indices); or it is the whole volume. The
// brick's faces inside `volume` are cut exactly and composite slabs lie on the grid through
// `slabAnchor` (DepthExtent::anchorDepth), so a brick read with its ghosts draws what the whole
// volume cut to the brick draws under the same anchor. `splats`: the volume's splats classified
// already (taken), or null. `note` gets the renderer's note and `ms` the frame's time. Throws.
std::vector<float> renderBrick(const Volume& volume, const VoxelBox& brick,
                               const TransferFunction& tf, const Camera& camera,
                               RenderSettings settings, int width, int height, double slabAnchor,
                               const std::string& backend, const std::string& shaderDir,
                               ClassifiedSplats* splats = nullptr, std::string* note = nullptr,
                               double* ms = nullptr);

// Opens the source on every rank, splits the whole voxel box into one brick per rank of `comm`,
// reads this rank's brick with its ghost voxels (BrickSource: alone where the format allows),
// agrees with the other ranks on the value range, histogram and transfer function, renders the
// brick and composites; rank 0 writes options.output: one picture, or with --turntable or --tour
// the frames of ewaview's camera path (writeFrames), one collective frame each. Returns the exit
// status (0, or 1 after one line on stderr from one rank), the same on every rank. Collective; an
// error after the ranks have agreed to go on (a composite failing on one rank) ends every rank
// through MPI_Abort after its line.
int renderDistributed(const Options& options, MPI_Comm comm);

class DistributedSession;
// Rank 0: --stats of the session's last frame as one JSON line: the ranks, the picture, the
// ghosts, the composite (the slowest rank's) and each rank's brick, render and composite
// times, bytes sent, voxels read and peak memory.
std::string frameStatsJson(const DistributedSession& session, int width, int height);

}  // namespace ewa::dist
