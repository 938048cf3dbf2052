// Where a distributed run's ranks read their bricks: the whole volume's grid from the file's
// metadata, and each brick's voxels (with its ghosts) read alone where the format allows.
#pragma once

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
  // Opens what `options` name (a file, --raw-dims, --synthetic): reads metadata only where the
  // format is read by parts (raw, NRRD raw, uncompressed MetaImage, OME-Zarr, HDF5, Marschner-
  // Lobb); otherwise loads the whole volume. Throws as loading does.
  static std::unique_ptr<BrickSource> open(const Options& options);

  const WholeGrid& grid() const { return grid_; }
  // The voxels of `region` (inside grid().dims, not empty) as a volume of their own, its
  // origin at the region's first voxel, so they sit where the whole volume's do. Its value
  // range and histogram are the region's own until the ranks agree on the whole's.
  virtual Volume read(const VoxelRegion& region) = 0;
  // "" when bricks are read alone; else one line saying that every rank reads the whole volume.
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

}  // namespace ewa::dist
