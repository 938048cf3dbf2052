// Where a distributed run's ranks read their bricks: the whole volume's grid from the file's
// metadata, and each brick's voxels (with its ghosts) read alone where the format allows, else
// sent by rank 0, which alone reads the whole file.
#pragma once

#include <mpi.h>

#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>

#include "app/options.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "io/region_read.h"

namespace ewa::dist {

// The whole volume's grid as every rank knows it without its voxels.
struct WholeGrid {
  std::array<int64_t, 3> dims{0, 0, 0};
  glm::dvec3 spacing{1.0};
  glm::dvec3 origin{0.0};
  glm::dmat3 direction{1.0};
  bool patientFrame = false;
  // Volume::worldPosition of index (i, j, k) and the world bounds of the corner voxels, as the
  // whole volume's (for the camera).
  glm::dvec3 worldPosition(const glm::dvec3& index) const;
  glm::dvec3 worldBoundsMin() const;
  glm::dvec3 worldBoundsMax() const;
  // The whole volume's default Volume::indexDataBox.
  DataBox indexDataBox() const;
};

class BrickSource {
 public:
  virtual ~BrickSource() = default;
  // Opens what `options` name (a file, --raw-dims, --synthetic) on every rank of `comm`: each
  // rank reads metadata only where the format is read by parts (raw, NRRD raw, uncompressed
  // MetaImage, OME-Zarr, HDF5, Marschner-Lobb); any other format rank 0 alone loads whole, and
  // sends the others its grid (scattered()). Collective. Returns null on every rank after one
  // rank said why in one line (anyFailed).
  static std::unique_ptr<BrickSource> open(const Options& options, MPI_Comm comm);
  // The same in one process without MPI (a format not read by parts is loaded whole and read()
  // cuts it). Throws as loading does.
  static std::unique_ptr<BrickSource> open(const Options& options);

  const WholeGrid& grid() const { return grid_; }
  // Whether rank 0 holds the whole volume and sends the ranks their regions (readShared).
  virtual bool scattered() const { return false; }
  // Whether the file is stored in chunks (OME-Zarr, HDF5), where a brick's ghost voxels would
  // read the neighbours' chunks too: the ranks read their bricks alone and trade the ghosts
  // (exchangeGhosts).
  virtual bool chunked() const { return false; }
  // This rank's `region` (inside grid().dims; empty: none, and an empty volume back) as a
  // volume of its own, its origin at the region's first voxel, so its voxels sit where the whole
  // volume's do. Its value range and histogram are the region's own until the ranks agree on the
  // whole's. Collective where scattered() (rank 0 sends each rank its region, which overlap by
  // their ghosts); else each rank reads alone. Throws on the ranks where it fails.
  virtual Volume readShared(const VoxelRegion& region, MPI_Comm comm);
  // The same read alone (not for a scattered() source).
  virtual Volume read(const VoxelRegion& region) = 0;
  // "" when bricks are read alone; else one line saying that rank 0 reads the whole volume and
  // sends each rank its region.
  const std::string& note() const { return note_; }
  // A synthetic volume's own transfer function; the file's sidecar transfer function path.
  const std::optional<TransferFunction>& ownTransferFunction() const { return ownTf_; }
  const std::string& sidecar() const { return sidecar_; }
  const std::string& name() const { return name_; }

 protected:
  WholeGrid grid_;
  std::string note_, sidecar_, name_;
  std::optional<TransferFunction> ownTf_;
};

// True for an empty region (no voxels).
bool emptyRegion(const VoxelRegion& region);

}  // namespace ewa::dist
