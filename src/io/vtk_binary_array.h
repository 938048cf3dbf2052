// Decoding of one VTK XML binary DataArray payload (appended raw or inline base64 bytes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/file_bytes.h"

namespace ewa {

struct VtkBinaryFormat {
  size_t headerWidth = 4;  // header_type UInt32 (4) or UInt64 (8)
  bool bigEndian = false;  // byte_order of the header integers (and of the data)
  bool zlib = false;       // compressor="vtkZLibDataCompressor"
};

// `source` starts at the array's header. Without compression: a byte count, then the data.
// With zlib: nblocks, blocksize, lastblocksize, nblocks compressed sizes, then the blocks.
// Returns exactly `expectedBytes` bytes in file byte order, or throws LoadError.
std::vector<uint8_t> decodeVtkBinaryArray(const std::string& path, const ByteSource& source,
                                          const VtkBinaryFormat& format, uint64_t expectedBytes);

}  // namespace ewa
