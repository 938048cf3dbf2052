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

// The file's voxel type: NIfTI's datatype codes of scalar numbers, and RGB24 and RGBA32 (bytes
// interleaved in each voxel: `components`).
FileScalar niftiType(const std::string& path, int datatype, int64_t* components) {
  *components = datatype == 128 ? 3 : datatype == 2304 ? 4 : 1;
  switch (datatype) {
    case 128:
    case 2304:
    case 2:
      return FileScalar::UInt8;
    case 4:
      return FileScalar::Int16;
    case 8:
      return FileScalar::Int32;
    case 16:
      return FileScalar::Float32;
    case 64:
      return FileScalar::Float64;
    case 256:
      return FileScalar::Int8;
    case 512:
      return FileScalar::UInt16;
    case 768:
      return FileScalar::UInt32;
    case 1024:
      return FileScalar::Int64;
    case 1280:
      return FileScalar::UInt64;
    default:
      failLoad(path, "unsupported NIfTI datatype " + std::to_string(datatype) +
                         " (supported: uint8, int8, int16, uint16, int32, uint32, int64, uint64, "
                         "float32, float64, RGB24, RGBA32)");
  }
}

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

Volume loadNifti(const std::string& path, int frame, int channel) {
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
  int64_t components = 1;
  const FileScalar type = niftiType(headerPath, h.datatype, &components);
  const size_t typeSize = fileScalarSize(type);
  VolumeLayout layout;
  layout.dims = {1, 1, 1};
  for (int a = 0; a < 3 && a < ndim; ++a) layout.dims[a] = h.dim[a + 1];
  const int64_t frames = ndim >= 4 ? h.dim[4] : 1;
  checkFrame(headerPath, frame, frames);

  // Sizes in the file's type first (checked against overflow and memory before any read).
  const uint64_t frameBytes = componentDataByteCount(headerPath, layout.dims, type, components);
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
    // Only the frame is kept: the frames before it are inflated and dropped.
    raw = inflateWindow(dataPath, packed.data(), packed.size(), start, end, "data");
    if (raw.size() < frameBytes)
      failLoad(dataPath, "data inflate to " + std::to_string(start + raw.size()) +
                             " bytes, fewer than the " + std::to_string(end) +
                             " that vox_offset and the dims need (truncated file?)");
  } else {
    const uint64_t size = regularFileSize(dataPath);
    if (start > size)
      failLoad(dataPath, "vox_offset " + std::to_string(offset) +
                             " is beyond the end of the file (" + std::to_string(size) + " bytes)");
    raw = readFileRange(dataPath, start, frameBytes);
  }
  if (h.bigEndian != hostIsBigEndian()) swapBytes(raw.data(), raw.size(), typeSize);

  placeNiftiInWorld(h, layout);
  layout.frame = frame;
  layout.frameCount = int(std::min<int64_t>(frames, std::numeric_limits<int>::max()));
  if (frames > 1)
    layout.notes.push_back("4D file with " + std::to_string(frames) + " frames; showing frame " +
                           std::to_string(frame) + " (--frame N picks another)");
  // Scaling applies when scl_slope is set and not the identity, never to colour (the standard);
  // makeVolume converts wide types.
  const bool scaled = h.sclSlope != 0.0 && std::isfinite(h.sclSlope) && std::isfinite(h.sclInter) &&
                      !(h.sclSlope == 1.0 && h.sclInter == 0.0) && components == 1;
  layout.bigEndian = hostIsBigEndian();
  layout.type = type;
  raw = pickComponent(headerPath, std::move(raw), components, channel, layout);
  if (dataPath != path) layout.sourceFiles.push_back(dataPath);
  if (headerPath != path) layout.sourceFiles.push_back(headerPath);
  if (!scaled) return makeVolume(path, layout, std::move(raw));
  const uint64_t count = frameBytes / typeSize;
  checkAllocation(headerPath, count * 4, "float32 volume");
  std::vector<uint8_t> out(size_t(count) * 4);
  for (uint64_t n = 0; n < count; ++n) {
    const auto v =
        float(fileScalarValue(type, &raw[size_t(n) * typeSize]) * h.sclSlope + h.sclInter);
    std::memcpy(&out[size_t(n) * 4], &v, 4);
  }
  layout.type = FileScalar::Float32;
  layout.notes.push_back(std::string(fileScalarName(type)) + " data scaled by scl_slope " +
                         std::to_string(h.sclSlope) + " and scl_inter " +
                         std::to_string(h.sclInter) + ", converted to float32");
  return makeVolume(path, layout, std::move(out));
}

}  // namespace ewa
