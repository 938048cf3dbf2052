// Reads a box of an OME-Zarr image's voxels from the chunk files overlapping it (loadZarr,
// loadZarrRegion).
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <new>

#include "io/byte_order.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/region_read.h"
#include "io/volume_layout.h"
#include "io/zarr_chunks.h"
#include "io/zarr_image.h"

namespace ewa {

namespace {

namespace fs = std::filesystem;

std::string boxText(const VoxelRegion& box) {
  std::string s;
  for (int i = 0; i < 3; ++i)
    s += (i ? ", " : "") + std::to_string(box.lo[size_t(i)]) + ".." +
         std::to_string(box.hi[size_t(i)]);
  return s;
}

void checkRegion(const std::string& path, const VoxelRegion& box,
                 const std::array<int64_t, 3>& dims) {
  for (size_t i = 0; i < 3; ++i)
    if (box.lo[i] < 0 || box.lo[i] >= box.hi[i] || box.hi[i] > dims[i])
      failLoad(path, "region " + boxText(box) + " is empty or not inside the volume's 0.." +
                         std::to_string(dims[0]) + ", 0.." + std::to_string(dims[1]) + ", 0.." +
                         std::to_string(dims[2]));
}

// Where the voxels of one chunk go: per array axis, the selected index range [lo, hi) and the
// stride (in voxels) of the output along it (0 for the time and channel axes, which select one).
struct Selection {
  std::vector<int64_t> lo, hi, outStride;
};

Selection selectionOf(const ZarrImage& image, int frame, int channel, const VoxelRegion& box) {
  const size_t rank = image.meta.shape.size();
  Selection s{std::vector<int64_t>(rank), std::vector<int64_t>(rank),
              std::vector<int64_t>(rank, 0)};
  if (image.timeAxis >= 0) s.lo[size_t(image.timeAxis)] = frame;
  if (image.channelAxis >= 0) s.lo[size_t(image.channelAxis)] = channel;
  for (size_t a = 0; a < rank; ++a) s.hi[a] = s.lo[a] + 1;
  int64_t stride = 1;
  for (size_t i = 0; i < 3; ++i) {
    const int a = image.spaceAxes[i];
    if (a >= 0) {
      s.lo[size_t(a)] = box.lo[i];
      s.hi[size_t(a)] = box.hi[i];
      s.outStride[size_t(a)] = stride;
    }
    stride *= box.hi[i] - box.lo[i];
  }
  return s;
}

std::string chunkKey(const std::vector<int64_t>& grid, char separator) {
  std::string key;
  for (size_t a = 0; a < grid.size(); ++a)
    key += (a ? std::string(1, separator) : "") + std::to_string(grid[a]);
  return key;
}

// The chunk's bytes, or empty when its file is missing (the fill value stands for it).
std::vector<uint8_t> readChunk(const ZarrImage& image, const std::string& key,
                               DataFileScope scope) {
  const std::string file = (fs::path(image.arrayFolder) / key).string();
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (status.type() == fs::file_type::not_found) return {};
  // Messages name the chunk within the image: "img.zarr: chunk 0/1.2.3: corrupt zstd chunk".
  const std::string label =
      image.path + ": chunk " + (image.levelName.empty() ? "" : image.levelName + "/") + key;
  checkDataFileScope(image.attributes, file, scope);
  const uint64_t size = regularFileSize(file);
  if (size > maxZarrChunkFileBytes(image.meta.chunkBytes))
    failLoad(label, "file of " + std::to_string(size) + " bytes is larger than a chunk of " +
                        std::to_string(image.meta.chunkBytes) + " bytes compresses to");
  const std::vector<uint8_t> stored = readFileRange(file, 0, size, "chunk");
  return decodeZarrChunk(label, image.meta.codec, stored.data(), stored.size(),
                         image.meta.chunkBytes);
}

// Copies the selected part of chunk `grid` (or its fill value) into `out`.
void placeChunk(const ZarrImage& image, const Selection& sel, const std::vector<int64_t>& grid,
                const std::vector<uint8_t>& chunk, const std::vector<uint8_t>& fill, uint8_t* out) {
  const std::vector<int64_t>& chunks = image.meta.chunks;
  const size_t rank = chunks.size(), item = fill.size();
  std::vector<int64_t> lo(rank), hi(rank), chunkStride(rank);
  int64_t stride = 1;
  for (size_t a = rank; a-- > 0;) {
    chunkStride[a] = stride;
    stride *= chunks[a];
    lo[a] = std::max(sel.lo[a], grid[a] * chunks[a]);
    hi[a] = std::min(sel.hi[a], (grid[a] + 1) * chunks[a]);
  }
  const size_t last = rank - 1;
  const size_t run = size_t(hi[last] - lo[last]);
  std::vector<int64_t> idx = lo;
  for (;;) {
    int64_t src = 0, dst = 0;
    for (size_t a = 0; a < rank; ++a) {
      src += (idx[a] - grid[a] * chunks[a]) * chunkStride[a];
      dst += (idx[a] - sel.lo[a]) * sel.outStride[a];
    }
    uint8_t* d = out + size_t(dst) * item;
    if (chunk.empty()) {
      for (size_t i = 0; i < run; ++i) std::memcpy(d + i * item, fill.data(), item);
    } else {
      std::memcpy(d, chunk.data() + size_t(src) * item, run * item);
    }
    // The odometer over every axis but the last (the contiguous run).
    size_t a = last;
    while (a-- > 0) {
      if (++idx[a] < hi[a]) break;
      idx[a] = lo[a];
    }
    if (a == size_t(-1)) break;
  }
}

Volume readZarr(const ZarrImage& image, int frame, int channel, const VoxelRegion& box,
                DataFileScope scope) {
  checkFrame(image.path, frame, image.frames(), "the image has", "time point");
  checkChannel(image.path, channel, image.channels());
  checkRegion(image.path, box, image.dims());
  VolumeLayout layout;
  for (size_t i = 0; i < 3; ++i) layout.dims[i] = box.hi[i] - box.lo[i];
  layout.type = image.meta.type;
  layout.bigEndian = image.meta.bigEndian;
  const uint64_t bytes = dataByteCount(image.path, layout.dims, layout.type);
  std::vector<uint8_t> data(bytes);
  std::vector<uint8_t> fill = encodeValues({image.meta.fillValue}, image.meta.type);
  if (image.meta.bigEndian != hostIsBigEndian()) swapBytes(fill.data(), fill.size(), fill.size());
  const Selection sel = selectionOf(image, frame, channel, box);
  // Every chunk that overlaps the selection, listed, then read and placed in parallel: each
  // writes its own voxels of `data`.
  const std::vector<int64_t>& chunks = image.meta.chunks;
  const size_t rank = chunks.size();
  std::vector<std::vector<int64_t>> grids;
  std::vector<int64_t> g(rank);
  for (size_t a = 0; a < rank; ++a) g[a] = sel.lo[a] / chunks[a];
  for (;;) {
    grids.push_back(g);
    size_t a = rank;
    while (a-- > 0) {
      if (++g[a] <= (sel.hi[a] - 1) / chunks[a]) break;
      g[a] = sel.lo[a] / chunks[a];
    }
    if (a == size_t(-1)) break;
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, grids.size()),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i) {
                        const std::vector<uint8_t> chunk =
                            readChunk(image, chunkKey(grids[i], image.meta.separator), scope);
                        placeChunk(image, sel, grids[i], chunk, fill, data.data());
                      }
                    });
  layout.spacing = image.spacing;
  for (int i = 0; i < 3; ++i)
    layout.origin[i] = image.origin[i] + box.lo[size_t(i)] * image.spacing[i];
  layout.unit = image.unit;
  layout.frame = frame, layout.frameCount = image.frames();
  layout.channel = channel, layout.channelCount = image.channels();
  layout.notes = image.notes;
  if (image.frames() > 1)
    layout.notes.push_back("time point " + std::to_string(frame) + " of " +
                           std::to_string(image.frames()) + " (--frame)");
  if (image.channels() > 1)
    layout.notes.push_back("channel " + std::to_string(channel) + " of " +
                           std::to_string(image.channels()) + " (--channel)");
  layout.sourceFiles.push_back(image.arrayFolder);
  return makeVolume(image.path, layout, std::move(data));
}

// Errors from metadata and chunk files inside the image start with the path the caller gave.
template <typename F>
auto namingPath(const std::string& path, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const LoadError& e) {
    const std::string message = e.what();
    if (message.compare(0, path.size() + 2, path + ": ") == 0) throw;
    failLoad(path, message);
  } catch (const std::bad_alloc&) {
    failLoad(path, "out of memory");
  }
}

VoxelRegion wholeVolume(const ZarrImage& image) {
  VoxelRegion box;
  box.hi = image.dims();
  return box;
}

}  // namespace

Volume loadZarr(const std::string& path, int level, int frame, int channel, DataFileScope scope) {
  return namingPath(path, [&] {
    const ZarrImage image = openZarrImage(path, level, scope);
    return readZarr(image, frame, channel, wholeVolume(image), scope);
  });
}

RegionSourceShape zarrShape(const std::string& path, int level) {
  return namingPath(path, [&] {
    const ZarrImage image = openZarrImage(path, level, DataFileScope::HeaderFolder);
    RegionSourceShape shape;
    shape.dims = image.dims();
    shape.spacing = image.spacing;
    shape.origin = image.origin;
    shape.type = image.meta.type;
    shape.frames = image.frames();
    shape.channels = image.channels();
    shape.levels = image.levels;
    return shape;
  });
}

Volume loadZarrRegion(const std::string& path, int level, int frame, int channel,
                      const VoxelRegion& box, DataFileScope scope) {
  return namingPath(path, [&] {
    const ZarrImage image = openZarrImage(path, level, scope);
    return readZarr(image, frame, channel, box, scope);
  });
}

}  // namespace ewa
