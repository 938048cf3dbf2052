// Writing a volume as an attached, gzip-compressed NRRD file (--save-volume).
#include "io/nrrd_writer.h"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/byte_order.h"

namespace ewa {

namespace {

// NRRD's name of the type: the volume's own ("uint8", "int16", "uint16"), but "float".
const char* nrrdType(ScalarType type) {
  return type == ScalarType::Float32 ? "float" : scalarName(type);
}

// Shortest text that reads back as the same double.
std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string vectorText(const glm::dvec3& v) {
  return "(" + number(v.x) + "," + number(v.y) + "," + number(v.z) + ")";
}

// gzip (zlib's deflate with a gzip wrapper), fed in pieces zlib can count.
std::string gzipBytes(const std::vector<uint8_t>& data) {
  z_stream zs{};
  if (deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("cannot start zlib");
  std::string out;
  std::vector<char> buffer(size_t{1} << 20);
  size_t at = 0;
  for (;;) {
    const size_t piece = std::min<size_t>(data.size() - at, size_t{1} << 30);
    zs.next_in = const_cast<Bytef*>(data.data() + at);
    zs.avail_in = uInt(piece);
    at += piece;
    const int flush = at == data.size() ? Z_FINISH : Z_NO_FLUSH;
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

bool isNrrdFileName(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  return name.size() > 5 && name.compare(name.size() - 5, 5, ".nrrd") == 0;
}

void writeNrrd(const std::string& path, const Volume& volume) {
  writeFileAtomically(path, encodeNrrd(volume));
}

}  // namespace ewa
