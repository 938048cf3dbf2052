// Size checks and final assembly shared by all loaders: the one place data becomes a Volume.
#include "io/volume_layout.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "core/shear_resample.h"
#include "core/volume_orientation.h"
#include "io/byte_order.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/text_numbers.h"

namespace ewa {

namespace {

ScalarType volumeScalarOf(FileScalar type) {
  switch (type) {
    case FileScalar::Int8:
    case FileScalar::Int16:
      return ScalarType::Int16;
    case FileScalar::UInt8:
      return ScalarType::UInt8;
    case FileScalar::UInt16:
      return ScalarType::UInt16;
    default:  // float32 and the wide types, which makeVolume converts to it
      return ScalarType::Float32;
  }
}

std::string sizesText(const std::array<int64_t, 3>& dims) {
  return std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " +
         std::to_string(dims[2]);
}

std::vector<uint8_t> widenInt8(const std::vector<uint8_t>& bytes) {
  std::vector<uint8_t> wide(bytes.size() * 2);
  for (size_t i = 0; i < bytes.size(); ++i) {
    const auto v = static_cast<int16_t>(static_cast<int8_t>(bytes[i]));
    const auto u = static_cast<uint16_t>(v);
    // Native order: write through a uint16_t.
    std::memcpy(wide.data() + 2 * i, &u, 2);
  }
  return wide;
}

// Wide values as float32; the note says so, and when integers lie beyond float32's exact
// range (2^24) or reals beyond its finite range, what that costs.
std::vector<uint8_t> narrowToFloat32(const std::string& path, const std::vector<uint8_t>& bytes,
                                     FileScalar type, std::vector<std::string>& notes) {
  const size_t size = fileScalarSize(type), count = bytes.size() / size;
  checkAllocation(path, uint64_t(count) * 4, "float32 volume");
  std::vector<uint8_t> out(count * 4);
  bool inexact = false, overflow = false;
  const bool integral = type != FileScalar::Float64;
  for (size_t i = 0; i < count; ++i) {
    const double v = fileScalarValue(type, &bytes[i * size]);
    const auto f = float(v);
    if (integral)
      inexact |= std::fabs(v) > 16777216.0;
    else
      overflow |= std::isfinite(v) && !std::isfinite(f);
    std::memcpy(&out[i * 4], &f, 4);
  }
  std::string note = std::string(fileScalarName(type)) + " data converted to float32";
  if (inexact) note += " (values beyond 16777216 are rounded)";
  if (overflow) note += " (values beyond float32's range became infinite)";
  notes.push_back(note);
  return out;
}

// A sheared grid (gantry tilt, skewed axes) resampled within each slice onto an upright one,
// so every value is drawn where the file puts it; one too sheared for that keeps its voxels and
// is drawn with the nearest rotation (makeRotation's warning). Returns the note saying which.
std::vector<std::string> resampleIfSheared(const std::string& path, OrientedGrid& grid,
                                           ScalarType type) {
  if (isOrthonormal(grid.direction)) return {};
  const ShearPlan plan = planShearResample(grid);
  if (!plan.ok)
    return {"the grid is sheared (gantry tilt or skewed axes) and not resampled: " + plan.problem};
  uint64_t count = 1;
  for (int64_t d : plan.dims) count *= uint64_t(d);
  checkAllocation(path, count * scalarSize(type), "the upright grid of a sheared one");
  *grid.bytes = resampleShear(plan, grid, type, smallestValue(*grid.bytes, type));
  grid.dims = plan.dims;
  grid.spacing = plan.spacing;
  grid.origin = plan.origin;
  grid.direction = plan.direction;
  char angle[32];
  std::snprintf(angle, sizeof angle, "%.1f", plan.skewDegrees);
  return {"the grid is sheared " + std::string(angle) +
          " degrees (gantry tilt or skewed axes): resampled within each slice onto " +
          sizesText(plan.dims) + " upright voxels"};
}

}  // namespace

uint64_t dataByteCount(const std::string& path, const std::array<int64_t, 3>& dims,
                       FileScalar type) {
  for (int64_t d : dims) {
    if (d <= 0) failLoad(path, "volume sizes " + sizesText(dims) + " must all be positive");
  }
  uint64_t bytes = fileScalarSize(type);
  for (int64_t d : dims) {
    if (__builtin_mul_overflow(bytes, static_cast<uint64_t>(d), &bytes)) {
      failLoad(path, "volume sizes " + sizesText(dims) + " of " + fileScalarName(type) +
                         " overflow 64-bit byte counts");
    }
  }
  // Volume indexes voxels with int64_t; keep the widened size in range too.
  if (bytes > uint64_t{INT64_MAX} / 2) {
    failLoad(path, "volume sizes " + sizesText(dims) + " are too large");
  }
  checkAllocation(path, bytes, "volume of " + sizesText(dims) + " " + fileScalarName(type));
  return bytes;
}

uint64_t componentDataByteCount(const std::string& path, const std::array<int64_t, 3>& dims,
                                FileScalar type, int64_t components) {
  if (components < 1 || components > 4096)
    failLoad(path, std::to_string(components) + " components a voxel (1 to 4096 are read)");
  const uint64_t one = dataByteCount(path, dims, type);
  uint64_t all = 0;
  if (__builtin_mul_overflow(one, uint64_t(components), &all) || all > uint64_t{INT64_MAX} / 2)
    failLoad(path, "volume sizes with " + std::to_string(components) + " components are too large");
  checkAllocation(path, all, "volume of " + std::to_string(components) + " components a voxel");
  return all;
}

std::vector<uint8_t> pickComponent(const std::string& path, std::vector<uint8_t> bytes,
                                   int64_t components, int channel, VolumeLayout& layout) {
  checkChannel(path, channel, components);
  if (components == 1) return bytes;
  layout.channel = channel;
  layout.channelCount = int(components);
  layout.notes.push_back(std::to_string(components) + " components a voxel; showing component " +
                         std::to_string(channel) + " (--channel N picks another)");
  const size_t size = fileScalarSize(layout.type);
  std::vector<uint8_t> out(bytes.size() / size_t(components));
  copyInterleaved(bytes.data() + size_t(channel) * size, size_t(components), size,
                  out.size() / size, out.data());
  return out;
}

Volume makeVolume(const std::string& path, const VolumeLayout& layout, std::vector<uint8_t> bytes) {
  const uint64_t expected = dataByteCount(path, layout.dims, layout.type);
  if (bytes.size() != expected) {
    failLoad(path, "read " + std::to_string(bytes.size()) + " data bytes, expected " +
                       std::to_string(expected));
  }
  glm::dvec3 spacing = layout.spacing;
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(spacing[a]) || spacing[a] == 0.0) {
      failLoad(path, "spacing along axis " + std::to_string(a) + " must be positive and finite");
    }
    spacing[a] = std::fabs(spacing[a]);  // a flipped axis: keep its magnitude
    if (!std::isfinite(layout.origin[a])) failLoad(path, "origin is not finite");
  }
  if (layout.bigEndian != hostIsBigEndian()) {
    swapBytes(bytes.data(), bytes.size(), fileScalarSize(layout.type));
  }
  std::vector<std::string> notes;
  if (layout.type == FileScalar::Int8) bytes = widenInt8(bytes);
  if (isWideScalar(layout.type)) bytes = narrowToFloat32(path, bytes, layout.type, notes);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (!std::isfinite(layout.direction[c][r])) failLoad(path, "direction is not finite");
  const ScalarType type = volumeScalarOf(layout.type);
  OrientedGrid grid{layout.dims, scalarSize(type), &bytes,
                    spacing,     layout.origin,    layout.direction};
  for (std::string& note : resampleIfSheared(path, grid, type)) notes.push_back(std::move(note));
  for (std::string& note : makeRotation(grid)) notes.push_back(std::move(note));
  // No instrument's step lies outside this, and squares and products of such numbers stay
  // exact enough for the camera and the writers (1e-314 is a denormal of 10 digits). Checked
  // on the grid as drawn: resampling a sheared one sets its own spacing.
  for (int a = 0; a < 3; ++a)
    if (grid.spacing[a] < 1e-100 || grid.spacing[a] > 1e100)
      failLoad(path, "spacing along axis " + std::to_string(a) + " is " +
                         shortText(grid.spacing[a]) +
                         ", outside 1e-100 to 1e100 (a corrupt header?)");
  try {
    Volume v(grid.dims, grid.spacing, grid.origin, type, std::move(bytes));
    v.setDirection(grid.direction, layout.patientFrame);
    v.setUnit(layout.unit);
    v.setFrame(layout.frame, layout.frameCount);
    v.setChannel(layout.channel, layout.channelCount);
    v.setSeriesChoices(layout.seriesChoices);
    for (const std::string& note : layout.notes) v.addNote(note);
    v.addSourceFile(path);
    for (const std::string& file : layout.sourceFiles)
      if (file != path) v.addSourceFile(file);
    for (std::string& note : notes) v.addNote(std::move(note));
    return v;
  } catch (const std::invalid_argument& e) {
    failLoad(path, e.what());
  }
}

}  // namespace ewa
