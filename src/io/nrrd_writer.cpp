// Encoding a volume as an attached, gzip-compressed NRRD file (--save-volume: writeVolume).
#include "io/nrrd_writer.h"

#include <stdexcept>

#include "io/byte_order.h"
#include "io/deflate_encode.h"
#include "io/text_numbers.h"

namespace ewa {

namespace {

// NRRD's name of the type: the volume's own ("uint8", "int16", "uint16"), but "float".
const char* nrrdType(ScalarType type) {
  return type == ScalarType::Float32 ? "float" : scalarName(type);
}

std::string vectorText(const glm::dvec3& v) {
  return "(" + roundTripText(v.x) + "," + roundTripText(v.y) + "," + roundTripText(v.z) + ")";
}

}  // namespace

std::string encodeNrrd(const Volume& volume) {
  const auto& d = volume.dims();
  std::string h = "NRRD0004\n# written by ewaview\n";
  for (const std::string& note : volume.notes()) {
    std::string line = note;
    for (char& c : line)
      if (c == '\n' || c == '\r') c = ' ';
    h += "# " + line + "\n";
  }
  h += std::string("type: ") + nrrdType(volume.type()) + "\ndimension: 3\n";
  h += std::string("space: ") +
       (volume.patientFrame() ? "left-posterior-superior" : "3D-right-handed") + "\n";
  h += "sizes: " + std::to_string(d[0]) + " " + std::to_string(d[1]) + " " + std::to_string(d[2]) +
       "\n";
  h += "space directions:";
  for (int a = 0; a < 3; ++a) h += " " + vectorText(volume.direction()[a] * volume.spacing()[a]);
  h += "\nkinds: domain domain domain\n";
  h += "space origin: " + vectorText(volume.origin()) + "\n";
  if (!volume.unit().empty()) {
    const std::string u = "\"" + volume.unit() + "\"";
    h += "space units: " + u + " " + u + " " + u + "\n";
  }
  h += "endian: little\nencoding: gzip\n\n";
  std::vector<uint8_t> bytes = volume.bytes();
  if (hostIsBigEndian()) swapBytes(bytes.data(), bytes.size(), scalarSize(volume.type()));
  return h + gzipBytes(bytes);
}

}  // namespace ewa
