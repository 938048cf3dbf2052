// Reading a box of a volume's voxels from formats stored in pieces (OME-Zarr chunks, HDF5
// hyperslabs), so that each process of a distributed run reads only its own brick.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "core/volume.h"
#include "io/file_bytes.h"
#include "io/file_scalar.h"
#include "io/volume_layout.h"

namespace ewa {

// Voxels lo <= (i, j, k) < hi, x first: a half-open box of voxel indices.
struct VoxelRegion {
  std::array<int64_t, 3> lo{0, 0, 0};
  std::array<int64_t, 3> hi{0, 0, 0};
};

// What a file holds, read from its metadata alone: enough to split the volume into bricks.
struct RegionSourceShape {
  std::array<int64_t, 3> dims{0, 0, 0};  // x, y, z
  glm::dvec3 spacing{1.0};
  glm::dvec3 origin{0.0};
  FileScalar type = FileScalar::UInt8;  // as stored (makeVolume widens or narrows it)
  int frames = 1, channels = 1, levels = 1;
};

// An OME-Zarr image (or a bare Zarr array) at pyramid level `level` (0: full resolution).
// Throws LoadError.
RegionSourceShape zarrShape(const std::string& path, int level);

// The voxels of `box` (inside zarrShape's dims, not empty) of time point `frame` and channel
// `channel` at `level`, read from the chunk files that overlap the box and no others. The
// volume's origin is the box's corner, so bricks read this way sit where the whole volume's
// voxels do; its value range and histogram are the box's. Throws LoadError.
Volume loadZarrRegion(const std::string& path, int level, int frame, int channel,
                      const VoxelRegion& box, DataFileScope scope = DataFileScope::HeaderFolder);

// An HDF5 file's 3D dataset (`dataset` a path inside the file, "" for the file's only one).
RegionSourceShape hdf5Shape(const std::string& path, const std::string& dataset);

// The voxels of `box` of that dataset, read as one hyperslab (no MPI-IO: each process opens the
// file alone and reads its own disjoint part). As loadZarrRegion otherwise.
Volume loadHdf5Region(const std::string& path, const std::string& dataset, const VoxelRegion& box);

// Where an uncompressed file's voxels lie: one run of dims product values from `offset` in
// `file`, x fastest, as the layout says (raw, NRRD with raw encoding, uncompressed MetaImage).
struct RawPlacement {
  VolumeLayout layout;  // the whole volume's
  std::string file;
  uint64_t offset = 0;
};

// A headerless file laid out as --raw-dims and its options say (loadRawVolume's layout).
RawPlacement rawFilePlacement(const std::string& path, const std::array<int64_t, 3>& dims,
                              FileScalar type, const glm::dvec3& spacing, bool bigEndian);
// A NRRD file's, when its 3D data are raw in one file (attached or detached); nothing for
// compressed or text encodings, several data files or a fourth axis. Throws LoadError.
std::optional<RawPlacement> nrrdRawPlacement(const std::string& path, DataFileScope scope);
// A MetaImage file's, when its data are uncompressed, of one channel. Throws LoadError.
std::optional<RawPlacement> metaImageRawPlacement(const std::string& path, DataFileScope scope);

// The bytes of a volume of `dims` values of `type` in a file, checked for positive sizes and
// 64-bit overflow but not against this process's memory (dataByteCount's check): a rank reads a
// box of a volume larger than its memory. Throws LoadError.
uint64_t wholeDataBytes(const std::string& path, const std::array<int64_t, 3>& dims,
                        FileScalar type);

// Whether loading the placement's whole volume (makeVolume) would only convert the values:
// the direction a rotation already, so nothing is resampled or reversed and a box of the file's
// voxels is that box of the loaded volume.
bool placementKeepsVoxelOrder(const RawPlacement& placement);

// The voxels of `box` (inside the layout's dims, not empty), read row by row (one seek and one
// read of the box's x-extent per row, slab by slab), converted as the whole volume's are
// (makeVolume). The origin is the box's corner, so the voxels sit where the whole volume's do.
// Throws LoadError. Needs placementKeepsVoxelOrder.
Volume loadRawRegion(const std::string& path, const RawPlacement& placement,
                     const VoxelRegion& box);

}  // namespace ewa
