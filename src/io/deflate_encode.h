// Deflate compression of a whole buffer, with gzip's or zlib's wrapper (the volume writers').
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ewa {

// `data` as one gzip member (zlib's deflate, level 6, with the gzip wrapper: NRRD's and
// .nii.gz's encoding), fed to zlib in pieces its 32-bit counts can hold. Throws
// std::runtime_error when zlib cannot start.
std::string gzipBytes(const uint8_t* data, size_t size);

// The same deflate stream with zlib's wrapper instead (MetaImage's CompressedData).
std::string zlibBytes(const uint8_t* data, size_t size);

inline std::string gzipBytes(const std::vector<uint8_t>& data) {
  return gzipBytes(data.data(), data.size());
}

}  // namespace ewa
