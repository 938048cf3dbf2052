// jpegHeaderProblem: the JPEG markers up to the first scan, checked as GDCM's codec needs them.
#include "io/jpeg_header_check.h"

#include <cstring>

namespace ewa {

namespace {

constexpr uint8_t kSoi = 0xD8, kEoi = 0xD9, kSos = 0xDA, kApp0 = 0xE0, kApp14 = 0xEE;

unsigned be16(const uint8_t* p) {
  return unsigned(p[0]) << 8 | p[1];
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

bool isJpegTransferSyntax(const std::string& uid) {
  // 1.2.840.10008.1.2.4.50 to .66 (baseline to the retired processes) and .70 (lossless SV1).
  const std::string prefix = "1.2.840.10008.1.2.4.";
  if (uid.compare(0, prefix.size(), prefix) != 0) return false;
  const std::string tail = uid.substr(prefix.size());
  const bool digits = tail.size() == 2 && tail[1] >= '0' && tail[1] <= '9';
  return digits && (tail[0] == '5' || tail[0] == '6' || tail == "70");
}

}  // namespace ewa
