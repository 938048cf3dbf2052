// Value prefilter: sharpens post-classified splats' values so the kernels' reconstruction of the
// field comes nearer interpolating the voxels, as a ray caster's trilinear samples do.
#pragma once

#include <cstdint>

#include "core/splat_set.h"
#include "core/volume.h"

namespace ewa {

// The strength post-classification uses unless told otherwise (--prefilter, the panel, the
// settings file). Measured on close-ups against VTK's ray caster at kernel width 0.7, cutoff 5
// (docs/rendering.md, "Value prefilter"): 0.05 brought aneurism, bonsai and engine nearest without
// amplifying CThead's noise, 0.1 and above overshoot at edges; with four samples a slab and the
// post-classified low-pass filter, 0.04 raises the worst of eleven views of each volume.
constexpr double kDefaultPrefilter = 0.04;
constexpr double kMaxPrefilter = 0.25;

// v + strength * (6 v - the sum of the 6 face neighbours): one step of undoing the smoothing a
// lattice of Gaussian kernels applies (a Gaussian of sigma s blurs a voxel into its neighbours
// by about exp(-1 / (2 s^2)) relative weight each; this adds back `strength` of the discrete
// Laplacian). Clamped to the volume's value range, since splats store values over it.
// Neighbours outside the volume or not finite count as the voxel itself, so the border is no
// edge. A NaN voxel stays NaN. strength 0: the voxel's value.
double prefilteredValue(const Volume& volume, int64_t i, int64_t j, int64_t k, double strength);

// Rewrites every splat's stored value with prefilteredValue. The set of splats is unchanged:
// which voxels are kept is decided from the data's own values. `threads` as parallelChunks
// takes it (0: the machine's cores); the values are the same for any count.
void prefilterSplatValues(const Volume& volume, double strength, SplatSet* splats,
                          unsigned threads = 0);

}  // namespace ewa
