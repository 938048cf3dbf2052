// Byte-level DICOM builders for the pre-check's tests: elements, nested sequences, deflated data
// sets and padding that GDCM's writers will not produce.
#pragma once

#include <zlib.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "loader_test_files.h"

namespace ewa::testing {

inline const char* const kExplicitLittle = "1.2.840.10008.1.2.1";
inline const char* const kImplicitLittle = "1.2.840.10008.1.2";
inline const char* const kDeflated = "1.2.840.10008.1.2.1.99";

// A text value padded to even length (UIs with a zero byte, others with a space).
inline std::string evenText(std::string text, char pad = ' ') {
  if (text.size() % 2) text += pad;
  return text;
}

// An explicit VR little-endian element of defined length.
inline std::string explicitElement(uint16_t group, uint16_t element, const std::string& vr,
                                   const std::string& value) {
  static const std::string kLong = "OBODOFOLOVOWSQSVUCUNURUTUV";
  bool longForm = false;
  for (size_t i = 0; i < kLong.size(); i += 2) longForm = longForm || kLong.compare(i, 2, vr) == 0;
  std::string out = uintBytes(group, 2) + uintBytes(element, 2) + vr;
  out += longForm ? std::string(2, '\0') + uintBytes(value.size(), 4) : uintBytes(value.size(), 2);
  return out + value;
}

// An implicit VR little-endian element of defined length.
inline std::string implicitElement(uint16_t group, uint16_t element, const std::string& value) {
  return uintBytes(group, 2) + uintBytes(element, 2) + uintBytes(value.size(), 4) + value;
}

// The header of an explicit element of undefined length (a sequence, or what GDCM refuses).
inline std::string undefinedLength(uint16_t group, uint16_t element, const std::string& vr) {
  return uintBytes(group, 2) + uintBytes(element, 2) + vr + std::string(2, '\0') +
         uintBytes(0xffffffffu, 4);
}
inline std::string itemStart(uint32_t length = 0xffffffffu) {
  return uintBytes(0xfffe, 2) + uintBytes(0xe000, 2) + uintBytes(length, 4);
}
inline std::string itemEnd() {
  return uintBytes(0xfffe, 2) + uintBytes(0xe00d, 2) + uintBytes(0, 4);
}
inline std::string sequenceEnd() {
  return uintBytes(0xfffe, 2) + uintBytes(0xe0dd, 2) + uintBytes(0, 4);
}

// `depth` sequences of undefined length, each the one item of the one above, the innermost
// holding a short text: as a nesting bomb builds them.
inline std::string nestedSequences(int depth) {
  std::string open, close;
  for (int d = 0; d < depth; ++d) {
    open += undefinedLength(0x0040, 0xa730, "SQ") + itemStart();  // Content Sequence
    close += itemEnd() + sequenceEnd();
  }
  return open + explicitElement(0x0040, 0xa160, "UT", "deep") + close;
}

// The meta header and preamble of a Part 10 file whose data set is in `syntax`.
inline std::string part10(const std::string& dataSet, const std::string& syntax,
                          const std::string& sopClass = "1.2.840.10008.5.1.4.1.1.7") {
  std::string meta = explicitElement(0x0002, 0x0001, "OB", std::string("\0\1", 2)) +
                     explicitElement(0x0002, 0x0002, "UI", evenText(sopClass, '\0')) +
                     explicitElement(0x0002, 0x0003, "UI", evenText("1.2.3.4.5.6", '\0')) +
                     explicitElement(0x0002, 0x0010, "UI", evenText(syntax, '\0')) +
                     explicitElement(0x0002, 0x0012, "UI", evenText("1.2.3.4", '\0'));
  meta = explicitElement(0x0002, 0x0000, "UL", uintBytes(meta.size(), 4)) + meta;
  return std::string(128, '\0') + "DICM" + meta + dataSet;
}

// A raw deflate stream (no zlib header or trailer) of `data`, as the deflated syntax holds it.
inline std::string rawDeflate(const std::string& data) {
  z_stream zs{};
  if (deflateInit2(&zs, 9, Z_DEFLATED, -MAX_WBITS, 9, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("deflateInit2 failed");
  std::string out(deflateBound(&zs, uLong(data.size())), '\0');
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  zs.avail_in = uInt(data.size());
  zs.next_out = reinterpret_cast<Bytef*>(out.data());
  zs.avail_out = uInt(out.size());
  const int ret = deflate(&zs, Z_FINISH);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  if (ret != Z_STREAM_END) throw std::runtime_error("deflate failed");
  return out;
}

// A small secondary-capture image data set (explicit VR little endian, in tag order): uint16
// pixels i + 10 j + 100 z of `columns` x `rows`, at z along the normal of an axial plane.
struct ByteImageSpec {
  int rows = 3, columns = 4;
  double z = 0.0;
  std::string seriesUid = "1.2.826.0.1.3680043.2.1125.77";
  std::string sopInstance = "1.2.826.0.1.3680043.2.1125.77.1";
  std::string modality = "OT";
  std::string sopClass = "1.2.840.10008.5.1.4.1.1.7";
  int frames = 1;                // more: NumberOfFrames, frame f's pixels plus 1000 f
  std::vector<uint16_t> pixels;  // instead of the pattern above
  // Further elements, in tag order: before (0008,0016); between (0008,0060) and (0020,000E);
  // between (0020,000E) and (0020,0032); between group 0028 and (7FE0,0010).
  std::string beforeSopClass, beforeSeries, beforePosition, beforePixels;
};
inline std::string imageDataSet(const ByteImageSpec& s) {
  std::vector<uint16_t> pixels = s.pixels;
  for (int f = 0; f < s.frames && s.pixels.empty(); ++f)
    for (int j = 0; j < s.rows; ++j)
      for (int i = 0; i < s.columns; ++i)
        pixels.push_back(uint16_t(i + 10 * j + 100 * int(s.z) + 1000 * f));
  char position[64];
  std::snprintf(position, sizeof position, "0\\0\\%g", s.z);
  return s.beforeSopClass + explicitElement(0x0008, 0x0016, "UI", evenText(s.sopClass, '\0')) +
         explicitElement(0x0008, 0x0018, "UI", evenText(s.sopInstance, '\0')) +
         explicitElement(0x0008, 0x0060, "CS", evenText(s.modality)) + s.beforeSeries +
         explicitElement(0x0020, 0x000e, "UI", evenText(s.seriesUid, '\0')) + s.beforePosition +
         explicitElement(0x0020, 0x0032, "DS", evenText(position)) +
         explicitElement(0x0020, 0x0037, "DS", evenText("1\\0\\0\\0\\1\\0")) +
         explicitElement(0x0028, 0x0002, "US", uintBytes(1, 2)) +
         explicitElement(0x0028, 0x0004, "CS", evenText("MONOCHROME2")) +
         (s.frames > 1 ? explicitElement(0x0028, 0x0008, "IS", evenText(std::to_string(s.frames)))
                       : std::string()) +
         explicitElement(0x0028, 0x0010, "US", uintBytes(uint64_t(s.rows), 2)) +
         explicitElement(0x0028, 0x0011, "US", uintBytes(uint64_t(s.columns), 2)) +
         explicitElement(0x0028, 0x0030, "DS", evenText("0.5\\0.5")) +
         explicitElement(0x0028, 0x0100, "US", uintBytes(16, 2)) +
         explicitElement(0x0028, 0x0101, "US", uintBytes(16, 2)) +
         explicitElement(0x0028, 0x0102, "US", uintBytes(15, 2)) +
         explicitElement(0x0028, 0x0103, "US", uintBytes(0, 2)) + s.beforePixels +
         explicitElement(0x7fe0, 0x0010, "OW", bytesOf(pixels));
}

}  // namespace ewa::testing
