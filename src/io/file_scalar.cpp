// The voxel types files store, their sizes and names, and values read and written as doubles.
#include "io/file_scalar.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

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
    case FileScalar::Int32:
    case FileScalar::UInt32:
      return 4;
    case FileScalar::Int64:
    case FileScalar::UInt64:
    case FileScalar::Float64:
      return 8;
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
    case FileScalar::Int32:
      return "int32";
    case FileScalar::UInt32:
      return "uint32";
    case FileScalar::Int64:
      return "int64";
    case FileScalar::UInt64:
      return "uint64";
    case FileScalar::Float64:
      return "float64";
  }
  return "?";
}

bool isWideScalar(FileScalar type) {
  return fileScalarSize(type) == 8 || type == FileScalar::Int32 || type == FileScalar::UInt32;
}

namespace {

template <typename T>
double valueAt(const uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return double(v);
}

// `v` rounded and clamped to T's range (integers) or narrowed (reals), stored at `p`.
template <typename T>
void putValue(uint8_t* p, double v) {
  T t;
  if constexpr (std::is_integral_v<T>) {
    // The clamp's upper end is the largest double below T's maximum, so the cast is defined.
    const double lo = double(std::numeric_limits<T>::min());
    const double hi = std::nextafter(double(std::numeric_limits<T>::max()) + 1.0, 0.0);
    t = std::isnan(v) ? T(0) : T(std::fmin(std::fmax(std::round(v), lo), hi));
  } else {
    t = T(v);
  }
  std::memcpy(p, &t, sizeof t);
}

}  // namespace

double fileScalarValue(FileScalar type, const uint8_t* p) {
  switch (type) {
    case FileScalar::Int8:
      return valueAt<int8_t>(p);
    case FileScalar::UInt8:
      return valueAt<uint8_t>(p);
    case FileScalar::Int16:
      return valueAt<int16_t>(p);
    case FileScalar::UInt16:
      return valueAt<uint16_t>(p);
    case FileScalar::Float32:
      return valueAt<float>(p);
    case FileScalar::Int32:
      return valueAt<int32_t>(p);
    case FileScalar::UInt32:
      return valueAt<uint32_t>(p);
    case FileScalar::Int64:
      return valueAt<int64_t>(p);
    case FileScalar::UInt64:
      return valueAt<uint64_t>(p);
    case FileScalar::Float64:
      return valueAt<double>(p);
  }
  return 0.0;
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

void copyInterleaved(const uint8_t* src, size_t stride, size_t bytes, size_t count, uint8_t* dst) {
  for (size_t x = 0; x < count; ++x) std::memcpy(dst + x * bytes, src + x * stride * bytes, bytes);
}

std::vector<uint8_t> encodeValues(const std::vector<double>& values, FileScalar type) {
  const size_t size = fileScalarSize(type);
  std::vector<uint8_t> out(values.size() * size);
  for (size_t i = 0; i < values.size(); ++i) {
    uint8_t* p = out.data() + i * size;
    const double v = values[i];
    switch (type) {
      case FileScalar::Int8:
        putValue<int8_t>(p, v);
        break;
      case FileScalar::UInt8:
        putValue<uint8_t>(p, v);
        break;
      case FileScalar::Int16:
        putValue<int16_t>(p, v);
        break;
      case FileScalar::UInt16:
        putValue<uint16_t>(p, v);
        break;
      case FileScalar::Float32:
        putValue<float>(p, v);
        break;
      case FileScalar::Int32:
        putValue<int32_t>(p, v);
        break;
      case FileScalar::UInt32:
        putValue<uint32_t>(p, v);
        break;
      case FileScalar::Int64:
        putValue<int64_t>(p, v);
        break;
      case FileScalar::UInt64:
        putValue<uint64_t>(p, v);
        break;
      case FileScalar::Float64:
        putValue<double>(p, v);
        break;
    }
  }
  return out;
}

}  // namespace ewa
