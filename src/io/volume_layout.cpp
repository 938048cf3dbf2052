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

namespace ewa {

size_t fileScalarSize(FileScalar type) {
  switch (type) {
    case FileScalar::Int8:
    case FileScalar::UInt8:
      return 1;
    case FileScalar::Int16:
    case FileScalar::UInt16:
      return 2;
    case FileScalar::Float32:
      return 4;
  }
  return 1;
}

const char* fileScalarName(FileScalar type) {
  switch (type) {
    case FileScalar::Int8:
      return "int8";
    case FileScalar::UInt8:
      return "uint8";
    case FileScalar::Int16:
      return "int16";
    case FileScalar::UInt16:
      return "uint16";
    case FileScalar::Float32:
      return "float32";
  }
  return "?";
}

FileScalar fileScalarOf(ScalarType type) {
  switch (type) {
    case ScalarType::UInt8:
      return FileScalar::UInt8;
    case ScalarType::Int16:
      return FileScalar::Int16;
    case ScalarType::UInt16:
      return FileScalar::UInt16;
    case ScalarType::Float32:
      return FileScalar::Float32;
  }
  return FileScalar::UInt8;
}

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
    case FileScalar::Float32:
      return ScalarType::Float32;
  }
  return ScalarType::UInt8;
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

std::vector<uint8_t> encodeValues(const std::vector<double>& values, FileScalar type) {
  std::vector<uint8_t> out(values.size() * fileScalarSize(type));
  for (size_t i = 0; i < values.size(); ++i) {
    uint8_t* p = out.data() + i * fileScalarSize(type);
    const double v = values[i];
    switch (type) {
      case FileScalar::UInt8:
        *p = uint8_t(std::fmin(std::fmax(std::round(v), 0.0), 255.0));
        break;
      case FileScalar::Int8:
        *p = uint8_t(int8_t(std::fmin(std::fmax(std::round(v), -128.0), 127.0)));
        break;
      case FileScalar::Int16: {
        const auto s = int16_t(std::fmin(std::fmax(std::round(v), -32768.0), 32767.0));
        std::memcpy(p, &s, 2);
        break;
      }
      case FileScalar::UInt16: {
        const auto s = uint16_t(std::fmin(std::fmax(std::round(v), 0.0), 65535.0));
        std::memcpy(p, &s, 2);
        break;
      }
      case FileScalar::Float32: {
        const auto f = float(v);
        std::memcpy(p, &f, 4);
        break;
      }
    }
  }
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
  if (layout.type == FileScalar::Int8) bytes = widenInt8(bytes);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (!std::isfinite(layout.direction[c][r])) failLoad(path, "direction is not finite");
  const ScalarType type = volumeScalarOf(layout.type);
  OrientedGrid grid{layout.dims, scalarSize(type), &bytes,
                    spacing,     layout.origin,    layout.direction};
  std::vector<std::string> notes = resampleIfSheared(path, grid, type);
  for (std::string& note : makeRotation(grid)) notes.push_back(std::move(note));
  try {
    Volume v(grid.dims, grid.spacing, grid.origin, type, std::move(bytes));
    v.setDirection(grid.direction, layout.patientFrame);
    v.setUnit(layout.unit);
    v.setFrame(layout.frame, layout.frameCount);
    v.setChannel(layout.channel, layout.channelCount);
    v.setSeriesChoices(layout.seriesChoices);
    for (const std::string& note : layout.notes) v.addNote(note);
    for (std::string& note : notes) v.addNote(std::move(note));
    return v;
  } catch (const std::invalid_argument& e) {
    failLoad(path, e.what());
  }
}

}  // namespace ewa
