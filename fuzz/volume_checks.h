// What every volume-loader fuzz target does with its input: load it, then check the result.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/volume.h"

namespace ewa::fuzz {

// Writes the input as "in<extension>" (plus data.N sections) and loads it with loadVolume.
// A LoadError is the expected answer to a bad file; a loaded volume must pass checkVolume.
void fuzzVolumeFile(const uint8_t* data, size_t size, const std::string& extension);

// Invariants of any loaded volume: data size = dims x type size, a rotation for direction,
// finite range with lo <= hi,
// a histogram counting only finite voxels, and (for small volumes) a splat set from the
// histogram's default transfer function with every splat inside the grid.
void checkVolume(const Volume& volume);

// Writes a small volume (up to 64 Ki voxels) as NRRD, NIfTI and MetaImage into `folder` and
// reads each back: the same grid, type and voxels, and the same placement (NIfTI to float
// precision). A writer may refuse only with one line naming the file (NIfTI: an axis over
// 32767 voxels, a placement float32 cannot hold).
void checkWrittenBack(const Volume& volume, const std::string& folder);

}  // namespace ewa::fuzz
