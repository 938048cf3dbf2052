// jpegHeaderProblem and jpeg2000HeaderProblem: JPEG markers up to the first scan, and a JPEG 2000
// codestream's image and tile size, checked as GDCM's codecs need them.
#include "io/jpeg_header_check.h"

#include <algorithm>
#include <cstring>

#include "io/byte_order.h"

namespace ewa {

namespace {

constexpr uint8_t kSoi = 0xD8, kEoi = 0xD9, kSos = 0xDA, kApp0 = 0xE0, kApp14 = 0xEE;

// Codec headers are big-endian.
unsigned be16(const uint8_t* p) {
  return unsigned(readUnsigned(p, 2, true));
}
uint64_t be32(const uint8_t* p) {
  return readUnsigned(p, 4, true);
}

// Start-of-frame markers: SOF0 to SOF15 but DHT (C4), JPG (C8) and DAC (CC).
bool isSof(uint8_t m) {
  return m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
}

// Markers libjpeg reads or skips in a header; anything else it stops on.
bool isKnownSegment(uint8_t m) {
  return isSof(m) || m == 0xC4 || m == 0xCC || m == 0xDB || m == 0xDC || m == 0xDD ||
         (m >= 0xE0 && m <= 0xEF) || m == 0xFE;
}

std::string hexByte(uint8_t v) {
  static const char kDigits[] = "0123456789ABCDEF";
  return std::string("0x") + kDigits[v >> 4] + kDigits[v & 15];
}

// GDCM's own walk over a codestream's markers (its parsej2k, to learn whether it is lossless)
// skips each segment by its length without looking at the bytes left, and reads COD's tenth
// byte: every segment it passes must lie inside the stream. It stops at the first SOD, or at a
// COD saying the wavelet is irreversible.
std::string jpeg2000MarkerProblem(const uint8_t* data, size_t size) {
  for (size_t pos = 2; size - pos >= 2;) {
    const unsigned marker = be16(&data[pos]);
    pos += 2;
    if (marker == 0xFF93) return "";  // SOD
    const bool noLength = (marker >= 0xFF30 && marker <= 0xFF3F) || marker == 0xFF4F ||
                          marker == 0xFFD9 || marker == 0xFF92;
    if (noLength) continue;
    if (size - pos < 2) return "";  // GDCM stops here too
    const unsigned length = be16(&data[pos]);
    pos += 2;
    if (length < 2) return "";  // and here
    if (length - 2 > size - pos) return "a marker segment longer than the stream";
    if (marker == 0xFF52) {  // COD
      if (length - 2 < 10) return "a coding style segment too short";
      if (data[pos + 9] == 0) return "";  // irreversible: GDCM's walk ends
    }
    pos += length - 2;
  }
  return "";
}

}  // namespace

std::string jpegHeaderProblem(const uint8_t* data, size_t size) {
  if (size < 2 || data[0] != 0xFF || data[1] != kSoi) return "";
  int sof = -1, precision = 0, components = 0, adobeTransform = -1;
  size_t pos = 2;
  while (true) {
    if (pos >= size) return "cut short";
    // libjpeg warns about bytes before a marker, and GDCM's codec aborts on the warning.
    if (data[pos] != 0xFF) return "stray bytes between markers";
    while (pos < size && data[pos] == 0xFF) ++pos;  // fill bytes
    if (pos >= size) return "cut short";
    const uint8_t marker = data[pos++];
    if (marker == kSos) break;
    if (marker == kEoi || marker == kSoi) return "no image";
    if ((marker >= 0xD0 && marker <= 0xD7) || marker == 0x01) continue;  // standalone markers
    if (!isKnownSegment(marker)) return "unknown marker " + hexByte(marker);
    if (size - pos < 2) return "cut short";
    const unsigned length = be16(&data[pos]);
    if (length < 2) return "a marker segment of length " + std::to_string(length);
    if (size - pos < length) return "cut short";
    const uint8_t* body = &data[pos + 2];
    const size_t bodySize = length - 2;
    if (isSof(marker)) {
      if (sof >= 0) return "two frame headers";
      sof = marker;
      if (bodySize < 6) return "frame header too short";
      precision = body[0];
      components = body[5];
      if (bodySize < 6 + 3 * size_t(components)) return "frame header too short";
    } else if (marker == kApp0 && bodySize >= 14 && std::memcmp(body, "JFIF\0", 5) == 0) {
      if (body[5] != 1) return "JFIF version " + std::to_string(body[5]) + " (1 only)";
    } else if (marker == kApp14 && bodySize >= 12 && std::memcmp(body, "Adobe", 5) == 0) {
      adobeTransform = body[11];
    }
    pos += length;
  }
  if (sof < 0) return "a scan before the frame header";
  // Baseline, extended sequential, progressive (Huffman) and lossless: what GDCM's codec has.
  if (sof > 0xC3) return "process " + hexByte(uint8_t(sof)) + " (arithmetic or hierarchical)";
  if (components != 1 && components != 3)
    return std::to_string(components) + " components (1 or 3)";
  if (components == 3 && adobeTransform > 1)
    return "Adobe colour transform " + std::to_string(adobeTransform);
  const bool lossless = sof == 0xC3;
  if (lossless ? precision < 8 || precision > 16
               : precision != 8 && precision != 12 && precision != 16)
    return "precision of " + std::to_string(precision) + " bits";
  return "";
}

std::string jpegLsHeaderProblem(const uint8_t* data, size_t size, int64_t columns, int64_t rows,
                                int64_t samples, int64_t bitsAllocated) {
  if (size < 2 || data[0] != 0xFF || data[1] != kSoi) return "";
  for (size_t pos = 2;;) {
    if (size - pos < 4) return "cut short";
    if (data[pos] != 0xFF) return "stray bytes between markers";
    const uint8_t marker = data[pos + 1];
    if (marker == kSos || marker == kEoi) return "a scan before the frame header";
    const unsigned length = be16(&data[pos + 2]);
    if (length < 2 || size - pos - 2 < length) return "cut short";
    if (marker == 0xF7) {  // SOF55: precision, lines, columns, components
      if (length < 8) return "frame header too short";
      const uint8_t* f = &data[pos + 4];
      const unsigned precision = f[0], lines = be16(f + 1), width = be16(f + 3), nc = f[5];
      if (lines != rows || width != columns)
        return "image of " + std::to_string(width) + " x " + std::to_string(lines) +
               " (the header says " + std::to_string(columns) + " x " + std::to_string(rows) + ")";
      if (int64_t(nc) != samples)
        return std::to_string(nc) + " components (SamplesPerPixel " + std::to_string(samples) + ")";
      // GDCM asserts when the decoded samples (1 byte up to 8 bits, else 2) overflow its buffer.
      if (precision < 2 || precision > 16 || (precision > 8 && bitsAllocated < 16))
        return "precision of " + std::to_string(precision) + " bits (BitsAllocated " +
               std::to_string(bitsAllocated) + ")";
      return "";
    }
    pos += 2 + length;
  }
}

std::string jpeg2000HeaderProblem(const uint8_t* data, size_t size, int64_t columns, int64_t rows,
                                  int64_t samples) {
  if (size < 4 || be16(data) != 0xFF4F) return "";  // no SOC: a JP2 box or a later fragment
  if (be16(data + 2) != 0xFF51) return "no SIZ marker after SOC";
  if (size < 6) return "cut short";
  const unsigned length = be16(data + 4);
  if (size - 4 < length || length < 41) return "cut short";
  const uint8_t* siz = data + 6;  // Rsiz, then the sizes
  const uint64_t width = be32(siz + 2), height = be32(siz + 6), x0 = be32(siz + 10),
                 y0 = be32(siz + 14), tileWidth = be32(siz + 18), tileHeight = be32(siz + 22),
                 tileX0 = be32(siz + 26), tileY0 = be32(siz + 30);
  const unsigned components = be16(siz + 34);
  if (length != 38 + 3 * components) return "SIZ length disagrees with its components";
  if (width <= x0 || height <= y0 || width - x0 != uint64_t(columns) ||
      height - y0 != uint64_t(rows))
    return "image of " + std::to_string(width - std::min(width, x0)) + " x " +
           std::to_string(height - std::min(height, y0)) + " (the header says " +
           std::to_string(columns) + " x " + std::to_string(rows) + ")";
  if (tileWidth == 0 || tileHeight == 0 || tileX0 > x0 || tileY0 > y0 || tileX0 + tileWidth <= x0 ||
      tileY0 + tileHeight <= y0)
    return "tiles that do not cover the image";
  if (int64_t(components) != samples)
    return std::to_string(components) + " components (SamplesPerPixel " + std::to_string(samples) +
           ")";
  for (unsigned c = 0; c < components; ++c) {
    const uint8_t* comp = siz + 36 + 3 * c;
    if ((comp[0] & 0x7F) + 1 > 16) return std::to_string((comp[0] & 0x7F) + 1) + "-bit samples";
    if (comp[1] != 1 || comp[2] != 1) return "subsampled components";
  }
  return jpeg2000MarkerProblem(data, size);
}

bool isJpegLsTransferSyntax(const std::string& uid) {
  return uid == "1.2.840.10008.1.2.4.80" || uid == "1.2.840.10008.1.2.4.81";
}

bool isJpeg2000TransferSyntax(const std::string& uid) {
  for (const char* j2k : {"1.2.840.10008.1.2.4.90", "1.2.840.10008.1.2.4.91",
                          "1.2.840.10008.1.2.4.92", "1.2.840.10008.1.2.4.93"})
    if (uid == j2k) return true;
  return false;
}

bool isJpegTransferSyntax(const std::string& uid) {
  // 1.2.840.10008.1.2.4.50 to .66 (baseline to the retired processes) and .70 (lossless SV1).
  const std::string prefix = "1.2.840.10008.1.2.4.";
  if (uid.compare(0, prefix.size(), prefix) != 0) return false;
  const std::string tail = uid.substr(prefix.size());
  const bool digits = tail.size() == 2 && tail[1] >= '0' && tail[1] <= '9';
  return digits && (tail[0] == '5' || tail[0] == '6' || tail == "70");
}

}  // namespace ewa
