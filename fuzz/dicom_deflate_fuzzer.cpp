// Fuzz target: a deflated DICOM file (transfer syntax 1.2.840.10008.1.2.1.99) whose inflated
// data set is the input, so mutations reach the structure the pre-check walks after inflating.
#include <zlib.h>

#include <string>

#include "fuzz_case.h"
#include "volume_checks.h"

namespace {

std::string littleEndian(uint64_t v, int width) {
  std::string out(size_t(width), '\0');
  for (int i = 0; i < width; ++i) out[size_t(i)] = char((v >> (8 * i)) & 0xff);
  return out;
}

// An explicit VR little-endian meta element of a short VR.
std::string metaElement(uint16_t element, const char* vr, std::string value) {
  if (value.size() % 2) value += '\0';
  return littleEndian(0x0002, 2) + littleEndian(element, 2) + vr + littleEndian(value.size(), 2) +
         value;
}

// A Part 10 file: preamble, meta header naming the deflated syntax, `data` raw-deflated.
std::string deflatedFile(const uint8_t* data, size_t size) {
  std::string meta = metaElement(0x0002, "UI", "1.2.840.10008.5.1.4.1.1.7") +
                     metaElement(0x0003, "UI", "1.2.3.4") +
                     metaElement(0x0010, "UI", "1.2.840.10008.1.2.1.99");
  meta = metaElement(0x0000, "UL", littleEndian(meta.size(), 4)) + meta;
  z_stream zs{};
  if (deflateInit2(&zs, 6, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK) return {};
  std::string stream(deflateBound(&zs, uLong(size)), '\0');
  zs.next_in = const_cast<Bytef*>(data);
  zs.avail_in = uInt(size);
  zs.next_out = reinterpret_cast<Bytef*>(stream.data());
  zs.avail_out = uInt(stream.size());
  const bool done = deflate(&zs, Z_FINISH) == Z_STREAM_END;
  stream.resize(zs.total_out);
  deflateEnd(&zs);
  return done ? std::string(128, '\0') + "DICM" + meta + stream : std::string();
}

}  // namespace

EWA_FUZZ_TARGET(dicom_deflate) {
  const std::string file = deflatedFile(data, size);
  if (file.empty()) return;
  ewa::fuzz::fuzzVolumeFile(reinterpret_cast<const uint8_t*>(file.data()), file.size(), ".dcm");
}
