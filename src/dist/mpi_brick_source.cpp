// BrickSource: bricks read by offsets, by chunks or hyperslabs, generated per box, or cut from
// the whole volume where the format is read only whole.
#include "dist/mpi_brick_source.h"

#include <algorithm>
#include <filesystem>

#include "app/scene.h"
#include "core/synthetic_volume.h"
#include "core/volume_crop.h"
#include "io/format_loaders.h"
#include "io/transfer_function_io.h"
#include "io/volume_loader.h"

namespace ewa::dist {

glm::dvec3 WholeGrid::worldPosition(const glm::dvec3& index) const {
  return origin + direction * (index * spacing);
}

glm::dvec3 WholeGrid::worldBoundsMin() const {
  glm::dvec3 out(INFINITY);
  for (int c = 0; c < 8; ++c)
    out = glm::min(out, worldPosition(glm::dvec3((c & 1) ? double(dims[0] - 1) : 0.0,
                                                 (c & 2) ? double(dims[1] - 1) : 0.0,
                                                 (c & 4) ? double(dims[2] - 1) : 0.0)));
  return out;
}

glm::dvec3 WholeGrid::worldBoundsMax() const {
  glm::dvec3 out(-INFINITY);
  for (int c = 0; c < 8; ++c)
    out = glm::max(out, worldPosition(glm::dvec3((c & 1) ? double(dims[0] - 1) : 0.0,
                                                 (c & 2) ? double(dims[1] - 1) : 0.0,
                                                 (c & 4) ? double(dims[2] - 1) : 0.0)));
  return out;
}

DataBox WholeGrid::indexDataBox() const {
  // As Volume::indexDataBox's default: between the outermost voxel centres, +-0.5 on an axis
  // one voxel thick.
  DataBox box;
  for (int axis = 0; axis < 3; ++axis) {
    const double top = double(std::max<int64_t>(dims[size_t(axis)], 1) - 1);
    box.low[axis] = top > 0.0 ? 0.0 : -0.5;
    box.high[axis] = top > 0.0 ? top : 0.5;
  }
  return box;
}

namespace {

void setGridFrom(const Volume& corner, const std::array<int64_t, 3>& dims, WholeGrid* grid) {
  grid->dims = dims;
  grid->spacing = corner.spacing();
  grid->origin = corner.origin();
  grid->direction = corner.direction();
  grid->patientFrame = corner.patientFrame();
}

const VoxelRegion kFirstVoxel{{0, 0, 0}, {1, 1, 1}};

// Raw, NRRD raw and uncompressed MetaImage: rows of the brick's x-extent read by offsets.
class PlacementSource : public BrickSource {
 public:
  PlacementSource(std::string path, RawPlacement placement)
      : path_(std::move(path)), placement_(std::move(placement)) {
    // The first voxel, converted as the whole would be, gives the grid's spacing and origin.
    setGridFrom(read(kFirstVoxel), placement_.layout.dims, &grid_);
  }
  Volume read(const VoxelRegion& region) override {
    return loadRawRegion(path_, placement_, region);
  }

 private:
  std::string path_;
  RawPlacement placement_;
};

// OME-Zarr: the chunk files that overlap the brick.
class ZarrSource : public BrickSource {
 public:
  ZarrSource(std::string path, const LoadOptions& load) : path_(std::move(path)), load_(load) {
    const RegionSourceShape shape = zarrShape(path_, load_.level);
    setGridFrom(read(kFirstVoxel), shape.dims, &grid_);
  }
  Volume read(const VoxelRegion& region) override {
    return loadZarrRegion(path_, load_.level, load_.frame, load_.channel, region, load_.dataFiles);
  }

 private:
  std::string path_;
  LoadOptions load_;
};

// HDF5: one hyperslab, each rank opening the file alone.
class Hdf5Source : public BrickSource {
 public:
  Hdf5Source(std::string path, std::string dataset)
      : path_(std::move(path)), dataset_(std::move(dataset)) {
    const RegionSourceShape shape = hdf5Shape(path_, dataset_);
    setGridFrom(read(kFirstVoxel), shape.dims, &grid_);
  }
  Volume read(const VoxelRegion& region) override {
    return loadHdf5Region(path_, dataset_, region);
  }

 private:
  std::string path_, dataset_;
};

// A synthetic volume evaluated voxel by voxel over the brick alone.
class SyntheticSource : public BrickSource {
 public:
  explicit SyntheticSource(SyntheticRegionSource source) : source_(std::move(source)) {
    SyntheticVolume corner = source_.make(kFirstVoxel.lo, kFirstVoxel.hi);
    setGridFrom(corner.volume, source_.dims, &grid_);
    ownTf_ = corner.transferFunction;
  }
  Volume read(const VoxelRegion& region) override {
    return source_.make(region.lo, region.hi).volume;
  }

 private:
  SyntheticRegionSource source_;
};

// Every other format: each rank loads the whole volume and keeps its brick.
class WholeSource : public BrickSource {
 public:
  WholeSource(Volume volume, const std::string& what,
              std::optional<TransferFunction> own = std::nullopt)
      : whole_(std::move(volume)) {
    ownTf_ = std::move(own);
    setGridFrom(whole_, whole_.dims(), &grid_);
    note_ =
        "every rank reads the whole of " + what + " (it is not read by parts) and keeps its brick";
  }
  Volume read(const VoxelRegion& region) override {
    VoxelRange range;
    for (size_t a = 0; a < 3; ++a) {
      range.low[a] = region.lo[a];
      range.high[a] = region.hi[a] - 1;
    }
    return cropVolume(whole_, range);
  }

 private:
  Volume whole_;
};

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

std::unique_ptr<BrickSource> openSource(const Options& o, const std::string& path) {
  if (!o.synthetic.empty()) {
    if (std::optional<SyntheticRegionSource> s = syntheticRegionSource(o.synthetic))
      return std::make_unique<SyntheticSource>(std::move(*s));
    SyntheticVolume s = makeSyntheticVolume(o.synthetic);
    return std::make_unique<WholeSource>(std::move(s.volume), "--synthetic " + o.synthetic,
                                         s.transferFunction);
  }
  const bool spacingGiven = o.load.spacing.has_value();
  if (!o.rawDims.empty()) {
    const RawOptions raw = parseRawOptions(o.rawDims, o.rawType, o.rawSpacing, o.rawEndian);
    RawPlacement p = rawFilePlacement(path, raw.dims, raw.type,
                                      o.load.spacing.value_or(raw.spacing), raw.bigEndian);
    return std::make_unique<PlacementSource>(path, std::move(p));
  }
  std::error_code ec;
  const std::string ext = lowerExtension(path);
  std::optional<RawPlacement> placement;
  if (ext == ".nrrd" || ext == ".nhdr") placement = nrrdRawPlacement(path, o.load.dataFiles);
  if ((ext == ".mhd" || ext == ".mha") && o.load.channel == 0)
    placement = metaImageRawPlacement(path, o.load.dataFiles);
  if (placement && placementKeepsVoxelOrder(*placement)) {
    if (spacingGiven) placement->layout.spacing = *o.load.spacing;
    return std::make_unique<PlacementSource>(path, std::move(*placement));
  }
  if (!spacingGiven) {
    if (isZarrPath(path) || (ext == ".zarr" && std::filesystem::is_directory(path, ec)))
      return std::make_unique<ZarrSource>(path, o.load);
    if (ext == ".h5" || ext == ".hdf5") return std::make_unique<Hdf5Source>(path, o.load.dataset);
  }
  return std::make_unique<WholeSource>(loadVolume(path, o.load, nullptr),
                                       std::filesystem::path(path).filename().string());
}

}  // namespace

std::unique_ptr<BrickSource> BrickSource::open(const Options& o) {
  const std::string path = o.file.empty() ? defaultVolumePath() : o.file;
  std::unique_ptr<BrickSource> source = openSource(o, path);
  if (o.synthetic.empty()) {
    source->sidecar_ = sidecarTransferFunctionPath(path, o.load.channel);
    source->name_ = std::filesystem::path(path).filename().string();
  } else {
    source->name_ = o.synthetic;
  }
  return source;
}

}  // namespace ewa::dist
