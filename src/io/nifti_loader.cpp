// NIfTI-1 and NIfTI-2 (.nii, .nii.gz, .hdr/.img): sizes checked, one frame read, scaled or widened.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "io/byte_order.h"
#include "io/decompress.h"
#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/nifti_header.h"
#include "io/text_fields.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

// The file's voxel type: its size in bytes and how a value is read.
struct NiftiType {
  const char* name;
  size_t size;
};

NiftiType niftiType(const std::string& path, int datatype) {
  switch (datatype) {
    case 2:
      return {"uint8", 1};
    case 4:
      return {"int16", 2};
    case 8:
      return {"int32", 4};
    case 16:
      return {"float32", 4};
    case 64:
      return {"float64", 8};
    case 256:
      return {"int8", 1};
    case 512:
      return {"uint16", 2};
    case 768:
      return {"uint32", 4};
    default:
      failLoad(path, "unsupported NIfTI datatype " + std::to_string(datatype) +
                         " (supported: uint8, int8, int16, uint16, int32, uint32, float32, "
                         "float64)");
  }
}

// One value of the file's type at `p` (already in native byte order) as a double.
double readValue(int datatype, const uint8_t* p) {
  switch (datatype) {
    case 2:
      return *p;
    case 256:
      return int8_t(*p);
    case 4: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case 512: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case 8: {
      int32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case 768: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case 16: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case 64: {
      double v;
      std::memcpy(&v, p, 8);
      return v;
    }
  }
  return 0.0;
}

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

Volume loadNifti(const std::string& path, int frame) {
  const std::string lower = toLower(path);
  const bool gzip = endsWith(lower, ".gz");
  const bool pair = endsWith(lower, ".hdr") || endsWith(lower, ".img") ||
                    endsWith(lower, ".hdr.gz") || endsWith(lower, ".img.gz");
  // A pair is read through its header whichever of the two files was named.
  std::string headerPath = path, dataPath = path;
  if (pair) {
    const std::string tail = gzip ? ".gz" : "";
    const std::string base = path.substr(0, path.size() - 4 - tail.size());
    headerPath = base + ".hdr" + tail;
    dataPath = base + ".img" + tail;
  }
  // Compressed files: the whole file is read and a prefix inflated as far as needed.
  std::vector<uint8_t> packed;
  const auto headerBytes = [&](const std::string& file) {
    const uint64_t size = regularFileSize(file);
    if (!gzip) return readFileRange(file, 0, std::min<uint64_t>(size, kNifti2Size), "header");
    checkAllocation(file, size, "compressed file");
    packed = readFileRange(file, 0, size, "compressed file");
    return inflatePrefix(file, packed.data(), packed.size(), kNifti2Size, "header");
  };
  const NiftiHeader h = parseNiftiHeader(headerPath, headerBytes(headerPath));

  const int64_t ndim = h.dim[0];
  if (ndim < 1 || ndim > 7) failLoad(headerPath, "bad NIfTI dim[0] " + std::to_string(ndim));
  for (int i = 1; i <= ndim; ++i)
    if (h.dim[i] < 1)
      failLoad(headerPath, "NIfTI dim[" + std::to_string(i) + "] = " + std::to_string(h.dim[i]) +
                               " is not positive");
  for (int i = 5; i <= ndim; ++i)
    if (h.dim[i] > 1)
      failLoad(headerPath, std::to_string(ndim) + "D NIfTI data (dim[" + std::to_string(i) +
                               "] = " + std::to_string(h.dim[i]) + ") is not supported (up to 4D)");
  const NiftiType type = niftiType(headerPath, h.datatype);
  VolumeLayout layout;
  layout.dims = {1, 1, 1};
  for (int a = 0; a < 3 && a < ndim; ++a) layout.dims[a] = h.dim[a + 1];
  const int64_t frames = ndim >= 4 ? h.dim[4] : 1;
  checkFrame(headerPath, frame, frames);

  // Sizes in the file's type first (checked against overflow and memory before any read).
  const FileScalar sizeProxy = type.size == 1   ? FileScalar::UInt8
                               : type.size == 2 ? FileScalar::UInt16
                                                : FileScalar::Float32;
  uint64_t frameBytes = dataByteCount(headerPath, layout.dims, sizeProxy);
  if (type.size == 8) frameBytes *= 2;  // float64: checked as float32, memory checked below
  checkAllocation(headerPath, frameBytes, "NIfTI frame");
  if (!std::isfinite(h.voxOffset) || h.voxOffset < 0.0 || h.voxOffset > 1e18)
    failLoad(headerPath, "bad vox_offset " + std::to_string(h.voxOffset));
  const auto offset = uint64_t(h.voxOffset);  // into the .img of a pair
  if (!pair && offset < (h.nifti2 ? kNifti2Size : kNifti1Size))
    failLoad(headerPath, "vox_offset " + std::to_string(offset) + " lies inside the header");
  uint64_t start = 0, end = 0;
  if (__builtin_mul_overflow(uint64_t(frame), frameBytes, &start) ||
      __builtin_add_overflow(start, offset, &start) ||
      __builtin_add_overflow(start, frameBytes, &end))
    failLoad(headerPath, "frame " + std::to_string(frame) + " lies beyond any file");

  std::vector<uint8_t> raw;
  if (gzip) {
    if (dataPath != headerPath) {
      const uint64_t size = regularFileSize(dataPath);
      checkAllocation(dataPath, size, "compressed file");
      packed = readFileRange(dataPath, 0, size, "compressed file");
    }
    std::vector<uint8_t> all = inflatePrefix(dataPath, packed.data(), packed.size(), end, "data");
    if (all.size() < end)
      failLoad(dataPath, "data inflate to " + std::to_string(all.size()) +
                             " bytes, fewer than "
                             "the " +
                             std::to_string(end) +
                             " that vox_offset and the dims need (truncated file?)");
    raw.assign(all.begin() + ptrdiff_t(start), all.end());
  } else {
    const uint64_t size = regularFileSize(dataPath);
    if (start > size)
      failLoad(dataPath, "vox_offset " + std::to_string(offset) +
                             " is beyond the end of the file (" + std::to_string(size) + " bytes)");
    raw = readFileRange(dataPath, start, frameBytes);
  }
  if (h.bigEndian != hostIsBigEndian()) swapBytes(raw.data(), raw.size(), type.size);

  placeNiftiInWorld(h, layout);
  layout.frame = frame;
  layout.frameCount = int(std::min<int64_t>(frames, std::numeric_limits<int>::max()));
  if (frames > 1)
    layout.notes.push_back("4D file with " + std::to_string(frames) + " frames; showing frame " +
                           std::to_string(frame) + " (--frame N picks another)");
  // Scaling applies when scl_slope is set and not the identity; wide types become float32.
  const bool scaled = h.sclSlope != 0.0 && std::isfinite(h.sclSlope) && std::isfinite(h.sclInter) &&
                      !(h.sclSlope == 1.0 && h.sclInter == 0.0);
  const bool wide = h.datatype == 8 || h.datatype == 768 || h.datatype == 64;
  if (!scaled && !wide) {
    layout.type = h.datatype == 2     ? FileScalar::UInt8
                  : h.datatype == 256 ? FileScalar::Int8
                  : h.datatype == 4   ? FileScalar::Int16
                  : h.datatype == 512 ? FileScalar::UInt16
                                      : FileScalar::Float32;
    layout.bigEndian = hostIsBigEndian();
    return makeVolume(path, layout, std::move(raw));
  }
  const uint64_t count = frameBytes / type.size;
  checkAllocation(headerPath, count * 4, "float32 volume");
  std::vector<uint8_t> out(size_t(count) * 4);
  const double slope = scaled ? h.sclSlope : 1.0, inter = scaled ? h.sclInter : 0.0;
  for (uint64_t n = 0; n < count; ++n) {
    const float v = float(readValue(h.datatype, &raw[size_t(n) * type.size]) * slope + inter);
    std::memcpy(&out[size_t(n) * 4], &v, 4);
  }
  layout.type = FileScalar::Float32;
  layout.bigEndian = hostIsBigEndian();
  layout.notes.push_back(std::string(type.name) + " data" +
                         (scaled ? " scaled by scl_slope " + std::to_string(h.sclSlope) +
                                       " and scl_inter " + std::to_string(h.sclInter)
                                 : std::string()) +
                         ", converted to float32");
  return makeVolume(path, layout, std::move(out));
}

}  // namespace ewa
