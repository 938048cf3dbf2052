// gzip compression of a whole buffer (the volume writers' encoding).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ewa {

// `data` as one gzip member (zlib's deflate, level 6, with the gzip wrapper), fed to zlib in
// pieces its 32-bit counts can hold. Throws std::runtime_error when zlib cannot start.
std::string gzipBytes(const uint8_t* data, size_t size);

inline std::string gzipBytes(const std::vector<uint8_t>& data) {
  return gzipBytes(data.data(), data.size());
}

}  // namespace ewa
