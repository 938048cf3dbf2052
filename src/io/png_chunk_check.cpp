// pngChunksProblem: every chunk's length checked against the bytes left.
#include "io/png_chunk_check.h"

#include "io/byte_order.h"

namespace ewa {

std::string pngChunksProblem(const uint8_t* data, size_t size) {
  size_t pos = 8;  // past the signature
  while (pos + 8 <= size) {
    const uint64_t length = readUnsigned(data + pos, 4, true);  // PNG is big-endian
    const std::string type(reinterpret_cast<const char*>(data + pos + 4), 4);
    if (length > size - pos - 8 || size - pos - 8 - length < 4)  // data and CRC
      return "the chunk at byte " + std::to_string(pos) + " claims " + std::to_string(length) +
             " bytes, past the file's end";
    if (type == "IEND") break;
    pos += 12 + size_t(length);
  }
  return "";
}

}  // namespace ewa
