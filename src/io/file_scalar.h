// The voxel types files store, their sizes and names, and values read and written as doubles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/volume.h"

namespace ewa {

// The voxel types files may store. Int8 has no Volume type: it is widened to Int16 on load.
// The wide types (32- and 64-bit integers, float64) are converted to float32 on load.
enum class FileScalar {
  Int8,
  UInt8,
  Int16,
  UInt16,
  Float32,
  Int32,
  UInt32,
  Int64,
  UInt64,
  Float64
};
size_t fileScalarSize(FileScalar type);
const char* fileScalarName(FileScalar type);
FileScalar fileScalarOf(ScalarType type);
// True for the types a Volume does not hold as they are (makeVolume makes them float32).
bool isWideScalar(FileScalar type);
// One value of `type` at `p`, in native byte order, as a double.
double fileScalarValue(FileScalar type, const uint8_t* p);

// Copies one value (`bytes` wide) of each of `count` groups from `src`, the groups `stride`
// values apart, to `dst` (contiguous): one channel of interleaved samples or components.
void copyInterleaved(const uint8_t* src, size_t stride, size_t bytes, size_t count, uint8_t* dst);

// `values` as `type`'s bytes (native order), integers rounded and clamped to the type's range:
// values a loader computed or parsed as numbers (DICOM after rescale, ASCII legacy VTK).
std::vector<uint8_t> encodeValues(const std::vector<double>& values, FileScalar type);

}  // namespace ewa
