// What a header says about the voxels, checked and turned into a Volume by every loader.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/volume.h"
#include "io/file_scalar.h"

namespace ewa {

struct VolumeLayout {
  std::array<int64_t, 3> dims{0, 0, 0};
  glm::dvec3 spacing{1.0};
  glm::dvec3 origin{0.0};
  FileScalar type = FileScalar::UInt8;
  bool bigEndian = false;     // byte order of the file's data
  glm::dmat3 direction{1.0};  // column a: world direction of axis a (any matrix; made a rotation)
  bool patientFrame = false;  // the world axes are LPS patient axes
  std::string unit;           // of spacing and origin ("mm"); "" when the file does not say
  int frame = 0, frameCount = 1;            // which of the file's volumes (Volume::frame)
  int channel = 0, channelCount = 1;        // which of its channels (Volume::channel)
  std::vector<SeriesChoice> seriesChoices;  // Volume::seriesChoices
  std::vector<std::string> notes;           // for Volume::notes
  std::vector<std::string> sourceFiles;     // read besides the file opened: Volume::sourceFiles
};

// Bytes of data the dims describe, after checking that every size is positive and that the
// product neither overflows 64 bits nor exceeds this machine's memory. Call it before reading
// or allocating anything for the data. Throws LoadError.
uint64_t dataByteCount(const std::string& path, const std::array<int64_t, 3>& dims,
                       FileScalar type);

// Bytes of data of `components` values a voxel (interleaved, as colour and vector images store
// them), after the same checks as dataByteCount; components must be 1 to 4096.
uint64_t componentDataByteCount(const std::string& path, const std::array<int64_t, 3>& dims,
                                FileScalar type, int64_t components);

// One component of interleaved data: `channel` of `components` values of `size` bytes a voxel.
// With one component the bytes come back as they are. Also picks the layout's channel: checks
// `channel` (checkChannel), sets layout.channel and channelCount and notes which it shows.
std::vector<uint8_t> pickComponent(const std::string& path, std::vector<uint8_t> bytes,
                                   int64_t components, int channel, VolumeLayout& layout);

// Builds the Volume from the file's data bytes: native byte order, Int8 widened to Int16,
// wide types converted to float32 (with a note; another on integers float32 cannot hold exactly),
// negative spacing taken by magnitude, zero or non-finite spacing/origin rejected, a sheared
// grid (gantry tilt) resampled within each slice onto an upright one (shear_resample.h), the
// direction made a rotation (makeRotation: a reflection reverses the slices).
Volume makeVolume(const std::string& path, const VolumeLayout& layout, std::vector<uint8_t> bytes);

}  // namespace ewa
