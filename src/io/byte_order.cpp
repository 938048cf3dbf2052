// Byte swapping for data whose file byte order differs from the host's.
#include "io/byte_order.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace ewa {

void swapBytes(uint8_t* data, size_t byteCount, size_t elementSize) {
  if (elementSize < 2) return;
  const size_t count = byteCount / elementSize;
  // The common sizes get a loop the compiler turns into byte-swap instructions.
  if (elementSize == 2) {
    for (size_t i = 0; i < count; ++i) std::swap(data[2 * i], data[2 * i + 1]);
    return;
  }
  if (elementSize == 4) {
    for (size_t i = 0; i < count; ++i) {
      uint32_t v;
      std::memcpy(&v, data + 4 * i, 4);
      v = __builtin_bswap32(v);
      std::memcpy(data + 4 * i, &v, 4);
    }
    return;
  }
  for (size_t i = 0; i < count; ++i) {
    uint8_t* e = data + i * elementSize;
    std::reverse(e, e + elementSize);
  }
}

uint64_t readUnsigned(const uint8_t* bytes, size_t width, bool bigEndian) {
  uint64_t value = 0;
  for (size_t i = 0; i < width; ++i) {
    const size_t shift = 8 * (bigEndian ? width - 1 - i : i);
    value |= static_cast<uint64_t>(bytes[i]) << shift;
  }
  return value;
}

}  // namespace ewa
