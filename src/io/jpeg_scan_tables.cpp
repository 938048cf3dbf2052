// jpegScanTablesProblem: every scan of a JPEG stream uses only tables defined before it.
#include <array>

#include "io/jpeg_header_check.h"

namespace ewa {

namespace {

bool isRestart(uint8_t m) {
  return m >= 0xD0 && m <= 0xD7;
}

struct Tables {
  std::array<bool, 8> huffman{};  // class (0 DC, 1 AC) * 4 + id
  std::array<bool, 4> quant{};
  std::array<int, 256> componentQuant{};  // the frame's components: their table, -1 none
  Tables() { componentQuant.fill(-1); }
};

// A DHT or DQT segment's tables marked defined; false when one is malformed (stb refuses it).
bool defineTables(uint8_t marker, const uint8_t* p, size_t n, Tables& t) {
  size_t at = 0;
  while (at < n) {
    const unsigned kind = p[at] >> 4, id = p[at] & 15;
    if (id > 3) return false;
    if (marker == 0xC4) {  // DHT: class and id, 16 counts, the values
      if (kind > 1 || n - at < 17) return false;
      size_t values = 0;
      for (int i = 1; i <= 16; ++i) values += p[at + i];
      if (n - at - 17 < values) return false;
      t.huffman[kind * 4 + id] = true;
      at += 17 + values;
    } else {  // DQT: precision and id, 64 values of 1 or 2 bytes
      const size_t bytes = 1 + 64 * (kind == 0 ? 1 : 2);
      if (kind > 1 || n - at < bytes) return false;
      t.quant[id] = true;
      at += bytes;
    }
  }
  return true;
}

// The scan's components must find their tables; "" when they do.
std::string scanProblem(const uint8_t* p, size_t n, const Tables& t) {
  if (n < 1 || n < 1 + 2 * size_t(p[0]) + 3) return "";  // malformed: stb refuses it
  const size_t count = p[0];
  const uint8_t ss = p[1 + 2 * count], se = p[2 + 2 * count], ah = p[3 + 2 * count] >> 4;
  for (size_t c = 0; c < count; ++c) {
    const uint8_t id = p[1 + 2 * c], dc = p[2 + 2 * c] >> 4, ac = p[2 + 2 * c] & 15;
    if (ss == 0 && ah == 0 && (dc > 3 || !t.huffman[dc]))
      return "a scan uses DC Huffman table " + std::to_string(dc) + " before any defines it";
    if (se > 0 && (ac > 3 || !t.huffman[4 + ac]))
      return "a scan uses AC Huffman table " + std::to_string(ac) + " before any defines it";
    const int q = t.componentQuant[id];
    if (q >= 0 && (q > 3 || !t.quant[size_t(q)]))
      return "a scan uses quantization table " + std::to_string(q) + " before any defines it";
  }
  return "";
}

}  // namespace

std::string jpegScanTablesProblem(const uint8_t* data, size_t size) {
  if (size < 2 || data[0] != 0xFF || data[1] != 0xD8) return "";
  Tables t;
  size_t pos = 2;
  while (pos + 1 < size) {
    if (data[pos] != 0xFF || data[pos + 1] == 0xFF) {  // stray or fill bytes, as stb skips them
      ++pos;
      continue;
    }
    const uint8_t marker = data[pos + 1];
    pos += 2;
    if (marker == 0xD9) return "";  // EOI
    if (marker == 0x00 || marker == 0x01 || isRestart(marker)) continue;
    if (size - pos < 2) return "";
    const size_t length = size_t(data[pos]) << 8 | data[pos + 1];
    if (length < 2 || length - 2 > size - pos - 2) return "";  // cut short: stb refuses it
    const uint8_t* body = data + pos + 2;
    const size_t n = length - 2;
    pos += length;
    if (marker == 0xC4 || marker == 0xDB) {
      if (!defineTables(marker, body, n, t)) return "";
    } else if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 &&
               marker != 0xCC) {  // a frame: its components' quantization tables
      if (n < 6) return "";
      const size_t count = body[5];
      if (n < 6 + 3 * count) return "";
      for (size_t c = 0; c < count; ++c) t.componentQuant[body[6 + 3 * c]] = body[8 + 3 * c];
    } else if (marker == 0xDA) {
      const std::string problem = scanProblem(body, n, t);
      if (!problem.empty()) return problem;
      // The scan's data runs to the next marker that is not a restart.
      while (pos + 1 < size && !(data[pos] == 0xFF && data[pos + 1] != 0x00 &&
                                 data[pos + 1] != 0xFF && !isRestart(data[pos + 1])))
        ++pos;
    }
  }
  return "";
}

}  // namespace ewa
