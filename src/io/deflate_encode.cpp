// Deflate compression of a whole buffer, with gzip's or zlib's wrapper (the volume writers').
#include "io/deflate_encode.h"

#include <zlib.h>

#include <algorithm>
#include <stdexcept>

namespace ewa {

namespace {

// windowBits 15 + 16 asks zlib for the gzip wrapper, 15 for its own.
std::string deflateBytes(const uint8_t* data, size_t size, int windowBits) {
  z_stream zs{};
  if (deflateInit2(&zs, 6, Z_DEFLATED, windowBits, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("cannot start zlib");
  std::string out;
  std::vector<char> buffer(size_t{1} << 20);
  size_t at = 0;
  for (;;) {
    const size_t piece = std::min<size_t>(size - at, size_t{1} << 30);
    zs.next_in = const_cast<Bytef*>(data + at);
    zs.avail_in = uInt(piece);
    at += piece;
    const int flush = at == size ? Z_FINISH : Z_NO_FLUSH;
    do {  // until deflate leaves room: all input taken (and, finishing, the stream ended)
      zs.next_out = reinterpret_cast<Bytef*>(buffer.data());
      zs.avail_out = uInt(buffer.size());
      deflate(&zs, flush);
      out.append(buffer.data(), buffer.size() - zs.avail_out);
    } while (zs.avail_out == 0);
    if (flush == Z_FINISH) break;
  }
  deflateEnd(&zs);
  return out;
}

}  // namespace

std::string gzipBytes(const uint8_t* data, size_t size) {
  return deflateBytes(data, size, 15 + 16);
}

std::string zlibBytes(const uint8_t* data, size_t size) {
  return deflateBytes(data, size, 15);
}

}  // namespace ewa
