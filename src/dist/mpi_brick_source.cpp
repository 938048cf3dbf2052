// BrickSource: bricks read by offsets, by chunks or hyperslabs, generated per box, or cut from
// the whole volume where the format is read only whole (by rank 0, which sends them).
#include "dist/mpi_brick_source.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "app/scene.h"
#include "core/synthetic_volume.h"
#include "core/volume_crop.h"
#include "dist/mpi_collective.h"
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
  bool chunked() const override { return true; }
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
  bool chunked() const override { return true; }
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

VoxelRange rangeOf(const VoxelRegion& region) {
  VoxelRange range;
  for (size_t a = 0; a < 3; ++a) {
    range.low[a] = region.lo[a];
    range.high[a] = region.hi[a] - 1;
  }
  return range;
}

// One process: the whole volume loaded, each region cut from it.
class WholeSource : public BrickSource {
 public:
  WholeSource(Volume volume, std::optional<TransferFunction> own) : whole_(std::move(volume)) {
    ownTf_ = std::move(own);
    setGridFrom(whole_, whole_.dims(), &grid_);
  }
  Volume read(const VoxelRegion& region) override { return cropVolume(whole_, rangeOf(region)); }

 private:
  Volume whole_;
};

// Bytes a message of a region carries at most: MPI counts are ints, and a region may hold more
// than 2 GiB; a bounded buffer also keeps rank 0 from copying a region whole.
constexpr size_t kChunkBytes = size_t(64) << 20;

// Every other format under MPI: rank 0 loads the whole volume and sends each rank its region
// (they overlap by their ghosts, so rank by rank); the others hold only their regions.
class ScatterSource : public BrickSource {
 public:
  // Rank 0 passes the whole volume; every rank the grid and type rank 0 broadcast.
  ScatterSource(Volume whole, const WholeGrid& grid, ScalarType type, const std::string& what)
      : whole_(std::move(whole)), type_(type) {
    grid_ = grid;
    note_ = "rank 0 reads the whole of " + what +
            " (it is not read by parts) and sends each rank its brick";
  }
  bool scattered() const override { return true; }
  Volume read(const VoxelRegion&) override {
    throw std::logic_error("a scattered source is read by every rank together (readShared)");
  }
  Volume readShared(const VoxelRegion& region, MPI_Comm comm) override {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    const int64_t mine[6] = {region.lo[0], region.lo[1], region.lo[2],
                             region.hi[0], region.hi[1], region.hi[2]};
    std::vector<int64_t> all(rank == 0 ? size_t(size) * 6 : 0);
    MPI_Gather(mine, 6, MPI_INT64_T, all.data(), 6, MPI_INT64_T, 0, comm);
    if (rank == 0) {
      for (int r = 1; r < size; ++r) {
        VoxelRegion theirs;
        for (size_t a = 0; a < 3; ++a) {
          theirs.lo[a] = all[size_t(r) * 6 + a];
          theirs.hi[a] = all[size_t(r) * 6 + 3 + a];
        }
        if (!emptyRegion(theirs)) send(theirs, r, comm);
      }
      return emptyRegion(region) ? Volume() : cropVolume(whole_, rangeOf(region));
    }
    if (emptyRegion(region)) return Volume();
    return receive(region, comm);
  }

 private:
  // Rank 0: the region's size, then its rows x fastest in chunks of at most kChunkBytes; -1 for
  // a region outside the volume (the ranks' grids differ), which the rank then reports.
  void send(const VoxelRegion& region, int to, MPI_Comm comm) const {
    const auto& d = whole_.dims();
    bool inside = true;
    for (size_t a = 0; a < 3; ++a)
      inside = inside && region.lo[a] >= 0 && region.hi[a] <= d[a] && region.lo[a] < region.hi[a];
    const size_t value = scalarSize(whole_.type());
    const size_t rowBytes = inside ? size_t(region.hi[0] - region.lo[0]) * value : 0;
    const int64_t total =
        inside ? int64_t(rowBytes) * (region.hi[1] - region.lo[1]) * (region.hi[2] - region.lo[2])
               : -1;
    MPI_Send(&total, 1, MPI_INT64_T, to, 0, comm);
    if (total <= 0) return;
    std::vector<uint8_t> chunk(std::min(size_t(total), kChunkBytes));
    size_t filled = 0;
    for (int64_t k = region.lo[2]; k < region.hi[2]; ++k)
      for (int64_t j = region.lo[1]; j < region.hi[1]; ++j) {
        const uint8_t* row =
            whole_.bytes().data() + size_t(whole_.index(region.lo[0], j, k)) * value;
        for (size_t done = 0; done < rowBytes;) {
          const size_t n = std::min(rowBytes - done, chunk.size() - filled);
          std::memcpy(chunk.data() + filled, row + done, n);
          filled += n;
          done += n;
          if (filled == chunk.size()) {
            MPI_Send(chunk.data(), int(filled), MPI_BYTE, to, 1, comm);
            filled = 0;
          }
        }
      }
    if (filled > 0) MPI_Send(chunk.data(), int(filled), MPI_BYTE, to, 1, comm);
  }

  // The others: the region's voxels in the chunks rank 0 sends, as cropVolume would cut them.
  Volume receive(const VoxelRegion& region, MPI_Comm comm) const {
    int64_t total = 0;
    MPI_Recv(&total, 1, MPI_INT64_T, 0, 0, comm, MPI_STATUS_IGNORE);
    if (total < 0)
      throw std::runtime_error(
          "rank 0 holds no such region of the volume (are the files the same "
          "on every node?)");
    std::vector<uint8_t> bytes(static_cast<size_t>(total));
    for (size_t at = 0; at < bytes.size();) {
      const size_t n = std::min(bytes.size() - at, kChunkBytes);
      MPI_Recv(bytes.data() + at, int(n), MPI_BYTE, 0, 1, comm, MPI_STATUS_IGNORE);
      at += n;
    }
    std::array<int64_t, 3> dims{};
    for (size_t a = 0; a < 3; ++a) dims[a] = region.hi[a] - region.lo[a];
    const glm::dvec3 origin = grid_.worldPosition(
        glm::dvec3(double(region.lo[0]), double(region.lo[1]), double(region.lo[2])));
    Volume v(dims, grid_.spacing, origin, type_, std::move(bytes));
    v.setDirection(grid_.direction, grid_.patientFrame);
    return v;
  }

  Volume whole_;  // rank 0 only
  ScalarType type_;
};

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// A source whose bricks each rank reads alone, or null for a format read only whole.
std::unique_ptr<BrickSource> openPartSource(const Options& o, const std::string& path) {
  if (!o.synthetic.empty()) {
    if (std::optional<SyntheticRegionSource> s = syntheticRegionSource(o.synthetic))
      return std::make_unique<SyntheticSource>(std::move(*s));
    return nullptr;
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
  return nullptr;
}

// The whole volume of a format read only whole, and a synthetic volume's own transfer function.
Volume loadWhole(const Options& o, const std::string& path, std::optional<TransferFunction>* own) {
  if (!o.synthetic.empty()) {
    SyntheticVolume s = makeSyntheticVolume(o.synthetic);
    *own = std::move(s.transferFunction);
    return std::move(s.volume);
  }
  return loadVolume(path, o.load, nullptr);
}

std::string wholeName(const Options& o, const std::string& path) {
  return o.synthetic.empty() ? std::filesystem::path(path).filename().string()
                             : "--synthetic " + o.synthetic;
}

void setNames(const Options& o, const std::string& path, std::string* sidecar, std::string* name) {
  if (o.synthetic.empty()) {
    *sidecar = sidecarTransferFunctionPath(path, o.load.channel);
    *name = std::filesystem::path(path).filename().string();
  } else {
    *name = o.synthetic;
  }
}

// What rank 0 tells the others of a volume it loaded whole: the grid and the voxel type.
struct GridMessage {
  double dims[3], spacing[3], origin[3], direction[9];
  double patientFrame, type, ownTfBytes;
};

}  // namespace

bool emptyRegion(const VoxelRegion& region) {
  for (size_t a = 0; a < 3; ++a)
    if (region.hi[a] <= region.lo[a]) return true;
  return false;
}

Volume BrickSource::readShared(const VoxelRegion& region, MPI_Comm) {
  return emptyRegion(region) ? Volume() : read(region);
}

std::unique_ptr<BrickSource> BrickSource::open(const Options& o) {
  const std::string path = o.file.empty() ? defaultVolumePath() : o.file;
  std::unique_ptr<BrickSource> source = openPartSource(o, path);
  if (!source) {
    std::optional<TransferFunction> own;
    Volume whole = loadWhole(o, path, &own);
    source = std::make_unique<WholeSource>(std::move(whole), std::move(own));
  }
  setNames(o, path, &source->sidecar_, &source->name_);
  return source;
}

std::unique_ptr<BrickSource> BrickSource::open(const Options& o, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const std::string path = o.file.empty() ? defaultVolumePath() : o.file;
  // Each rank opens a format read by parts itself; a rank that cannot says so for all.
  std::unique_ptr<BrickSource> source;
  std::string error;
  try {
    source = openPartSource(o, path);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (anyFailed(error, comm)) return nullptr;
  const bool whole = !source;
  if (differsFromRank0(whole ? 1 : 0,
                       "this rank opens another kind of volume than rank 0 (are the files the "
                       "same on every node?)",
                       comm))
    return nullptr;
  if (whole) {
    // Rank 0 alone loads the file and tells the others its grid, voxel type and, for a synthetic
    // volume, its own transfer function; they never hold more than their regions.
    Volume volume;
    std::optional<TransferFunction> own;
    try {
      if (rank == 0) volume = loadWhole(o, path, &own);
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (anyFailed(error, comm)) return nullptr;
    GridMessage m{};
    std::string tfJson;
    if (rank == 0) {
      WholeGrid g;
      setGridFrom(volume, volume.dims(), &g);
      for (int a = 0; a < 3; ++a) {
        m.dims[a] = double(g.dims[size_t(a)]);
        m.spacing[a] = g.spacing[a];
        m.origin[a] = g.origin[a];
        for (int b = 0; b < 3; ++b) m.direction[a * 3 + b] = g.direction[a][b];
      }
      m.patientFrame = g.patientFrame ? 1.0 : 0.0;
      m.type = double(int(volume.type()));
      if (own) tfJson = transferFunctionToJson(*own);
      m.ownTfBytes = own ? double(tfJson.size()) : -1.0;
    }
    MPI_Bcast(&m, int(sizeof m / sizeof(double)), MPI_DOUBLE, 0, comm);
    WholeGrid g;
    for (int a = 0; a < 3; ++a) {
      g.dims[size_t(a)] = int64_t(m.dims[a]);
      g.spacing[a] = m.spacing[a];
      g.origin[a] = m.origin[a];
      for (int b = 0; b < 3; ++b) g.direction[a][b] = m.direction[a * 3 + b];
    }
    g.patientFrame = m.patientFrame != 0.0;
    if (m.ownTfBytes >= 0.0) {
      tfJson.resize(size_t(m.ownTfBytes));
      MPI_Bcast(tfJson.data(), int(tfJson.size()), MPI_CHAR, 0, comm);
      try {
        if (rank != 0) own = parseTransferFunctionJson(tfJson, wholeName(o, path));
      } catch (const std::exception& e) {
        error = e.what();
      }
      if (anyFailed(error, comm)) return nullptr;
    }
    source = std::make_unique<ScatterSource>(std::move(volume), g, ScalarType(int(m.type)),
                                             wholeName(o, path));
    source->ownTf_ = std::move(own);
  }
  setNames(o, path, &source->sidecar_, &source->name_);
  return source;
}

}  // namespace ewa::dist
