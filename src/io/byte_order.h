// Endianness: swapping data to native order and reading integers of a given byte order.
#pragma once

#include <cstddef>
#include <cstdint>

namespace ewa {

// True on big-endian hosts.
constexpr bool hostIsBigEndian() {
#if defined(__BYTE_ORDER__) && defined(__ORDER_BIG_ENDIAN__)
  return __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;
#else
  return false;
#endif
}

// Reverses the bytes of each `elementSize`-byte element (1 = nothing to do). A trailing partial
// element is left alone.
void swapBytes(uint8_t* data, size_t byteCount, size_t elementSize);

// Reads an unsigned integer of `width` bytes (1, 2, 4 or 8) stored with the given byte order.
uint64_t readUnsigned(const uint8_t* bytes, size_t width, bool bigEndian);

}  // namespace ewa
