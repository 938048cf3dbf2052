// Post-classified splatting: which voxels become splats when the transfer function is applied
// per pixel to the reconstructed value instead of per voxel before splatting.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/volume.h"

namespace ewa {

// pre: each voxel's colour and opacity are splatted (the paper's method). post: the data value
// is splatted; each slab's kernel-weighted mean value is classified per pixel (Mueller et al.,
// "Splatting Without the Blur", 1999).
enum class ClassificationMode { Pre = 0, Post = 1 };

const char* classificationModeName(ClassificationMode mode);
// Parses "pre" or "post"; false for anything else.
bool parseClassificationMode(const std::string& text, ClassificationMode* mode);
std::vector<std::string> classificationModeNames();  // every name parseClassificationMode accepts

// The squared distance in voxel steps within which a kernel reaches (cutoff * kernel width^2,
// rounded down), 1 to 225: the margin of zero-opacity voxels that must stay beside visible ones
// so that the mean value near a boundary is the reconstructed one, not the mean of the visible
// voxels alone.
int postClassificationMarginSquared(double cutoff, double kernelWidth);

// One byte a voxel (Volume::index order), 1 where a post-classified frame needs the voxel: its
// value has non-zero opacity, or the segment between it and an invisible 6-neighbour's value
// crosses one (a transfer-function peak between two voxel values, which interpolation passes
// through), or such a voxel lies within squared Euclidean distance `marginSquared` (in voxel
// steps, at most 225; a ball, as far as a kernel reaches in every direction). `isVisible` is asked
// on a 4096-entry table over the value range, not per voxel, from several threads at once.
// `threads` as parallelChunks takes it (0: the machine's cores); the mask is the same for any.
std::vector<uint8_t> postClassificationMask(const Volume& volume,
                                            const std::function<bool(double)>& isVisible,
                                            int marginSquared, unsigned threads = 0);

}  // namespace ewa
