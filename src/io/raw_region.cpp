// Reading a box of an uncompressed file's voxels by offsets (raw, NRRD raw, MetaImage), so that
// each process of a distributed run reads only its brick.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/mat3x3.hpp>
#include <memory>
#include <vector>

#include "io/file_bytes.h"
#include "io/load_failure.h"
#include "io/region_read.h"

namespace ewa {

RawPlacement rawFilePlacement(const std::string& path, const std::array<int64_t, 3>& dims,
                              FileScalar type, const glm::dvec3& spacing, bool bigEndian) {
  RawPlacement p;
  p.layout.dims = dims;
  p.layout.type = type;
  p.layout.spacing = spacing;
  p.layout.bigEndian = bigEndian;
  p.file = path;
  return p;
}

uint64_t wholeDataBytes(const std::string& path, const std::array<int64_t, 3>& dims,
                        FileScalar type) {
  uint64_t bytes = fileScalarSize(type);
  for (int64_t d : dims)
    if (d <= 0 || __builtin_mul_overflow(bytes, uint64_t(d), &bytes) ||
        bytes > uint64_t{INT64_MAX} / 2)
      failLoad(path, "the volume's sizes must be positive and within 64-bit byte counts");
  return bytes;
}

bool placementKeepsVoxelOrder(const RawPlacement& placement) {
  // makeVolume resamples a sheared grid and reverses a reflected one: then a box of the file
  // is not the same box of the volume. A rotation (to rounding) it leaves as it is.
  const glm::dmat3& d = placement.layout.direction;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double dot = 0.0;
      for (int r = 0; r < 3; ++r) dot += d[a][r] * d[b][r];
      if (std::abs(dot - (a == b ? 1.0 : 0.0)) > 1e-9) return false;
    }
  return glm::determinant(d) > 0.0;
}

Volume loadRawRegion(const std::string& path, const RawPlacement& placement,
                     const VoxelRegion& box) {
  const VolumeLayout& whole = placement.layout;
  std::array<int64_t, 3> size{};
  for (int a = 0; a < 3; ++a) {
    if (box.lo[size_t(a)] < 0 || box.hi[size_t(a)] > whole.dims[size_t(a)] ||
        box.lo[size_t(a)] >= box.hi[size_t(a)])
      failLoad(path, "the box to read lies outside the volume");
    size[size_t(a)] = box.hi[size_t(a)] - box.lo[size_t(a)];
  }
  if (!placementKeepsVoxelOrder(placement))
    failLoad(path, "a sheared or reflected grid cannot be read in boxes");
  VolumeLayout layout = whole;
  layout.dims = size;
  const uint64_t value = fileScalarSize(whole.type);
  const uint64_t bytesWanted = dataByteCount(path, size, whole.type);
  // The file must hold the whole volume (a truncated file fails as the whole load would); the
  // whole need not fit this process's memory, only the box (dataByteCount above).
  const uint64_t wholeBytes = wholeDataBytes(path, whole.dims, whole.type);
  const uint64_t fileSize = regularFileSize(placement.file);
  if (fileSize < placement.offset || fileSize - placement.offset < wholeBytes)
    failLoad(placement.file, "file has " + std::to_string(fileSize) + " bytes, too few for the " +
                                 std::to_string(wholeBytes) + " bytes of data at offset " +
                                 std::to_string(placement.offset));
  std::vector<uint8_t> bytes(static_cast<size_t>(bytesWanted));
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(placement.file.c_str(), "rb"),
                                                       std::fclose);
  if (!file) failLoad(placement.file, std::strerror(errno));
  const uint64_t rowBytes = uint64_t(size[0]) * value;
  uint8_t* to = bytes.data();
  for (int64_t k = box.lo[2]; k < box.hi[2]; ++k)
    for (int64_t j = box.lo[1]; j < box.hi[1]; ++j, to += rowBytes) {
      const uint64_t voxel =
          uint64_t(box.lo[0]) +
          uint64_t(whole.dims[0]) * (uint64_t(j) + uint64_t(whole.dims[1]) * uint64_t(k));
      if (fseeko(file.get(), off_t(placement.offset + voxel * value), SEEK_SET) != 0 ||
          std::fread(to, 1, size_t(rowBytes), file.get()) != rowBytes)
        failLoad(placement.file, "too short for its volume (truncated file or wrong sizes?)");
    }
  // Where voxel lo sits in the whole volume: origin + D * (lo * |spacing|), as makeVolume has it.
  const glm::dvec3 lo(double(box.lo[0]), double(box.lo[1]), double(box.lo[2]));
  layout.origin = whole.origin + whole.direction * (lo * glm::abs(whole.spacing));
  return makeVolume(path, layout, std::move(bytes));
}

}  // namespace ewa
