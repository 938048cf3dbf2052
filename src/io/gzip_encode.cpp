// gzip compression of a whole buffer (the volume writers' encoding).
#include "io/gzip_encode.h"

#include <zlib.h>

#include <algorithm>
#include <stdexcept>

namespace ewa {

std::string gzipBytes(const uint8_t* data, size_t size) {
  z_stream zs{};
  if (deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
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

}  // namespace ewa
