// Legacy VTK files (.vtk) of STRUCTURED_POINTS: point scalars, ASCII or big-endian binary.
#include <cmath>
#include <string>
#include <vector>

#include "io/byte_order.h"
#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/text_fields.h"
#include "io/text_numbers.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

constexpr uint64_t kMaxHeaderBytes = 1 << 16;

// The header's lines, one at a time, and where the data starts after the last one taken.
class HeaderLines {
 public:
  HeaderLines(const std::string& path, std::string text) : path_(path), text_(std::move(text)) {}
  std::string next(const char* expected) {
    const size_t end = text_.find('\n', pos_);
    if (end == std::string::npos)
      failLoad(path_, std::string("the header ends before ") + expected);
    std::string line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return line;
  }
  // The next line that is not blank, as words.
  std::vector<std::string> words(const char* expected) {
    for (;;) {
      const std::vector<std::string> w = splitWords(next(expected), " \t\r");
      if (!w.empty()) return w;
    }
  }
  uint64_t offset() const { return pos_; }

 private:
  std::string path_;
  std::string text_;
  size_t pos_ = 0;
};

FileScalar scalarType(const std::string& path, const std::string& name) {
  // "long" as VTK writes it on 64-bit Linux and macOS: 8 bytes.
  static const std::pair<const char*, FileScalar> kTypes[] = {
      {"unsigned_char", FileScalar::UInt8},
      {"char", FileScalar::Int8},
      {"signed_char", FileScalar::Int8},
      {"unsigned_short", FileScalar::UInt16},
      {"short", FileScalar::Int16},
      {"float", FileScalar::Float32},
      {"int", FileScalar::Int32},
      {"unsigned_int", FileScalar::UInt32},
      {"long", FileScalar::Int64},
      {"vtktypeint64", FileScalar::Int64},
      {"unsigned_long", FileScalar::UInt64},
      {"vtktypeuint64", FileScalar::UInt64},
      {"double", FileScalar::Float64}};
  const std::string t = toLower(name);
  for (const auto& [n, type] : kTypes)
    if (t == n) return type;
  failLoad(path, "SCALARS of type " + quoteText(name) +
                     " are not read (unsigned_char, char, short, unsigned_short, int, "
                     "unsigned_int, long, unsigned_long, float, double)");
}

}  // namespace

Volume loadVtkLegacy(const std::string& path, int channel) {
  const uint64_t size = regularFileSize(path);
  const std::vector<uint8_t> head = readFileRange(path, 0, std::min(size, kMaxHeaderBytes));
  HeaderLines lines(path, std::string(head.begin(), head.end()));
  if (lines.next("its version line").rfind("# vtk DataFile", 0) != 0)
    failLoad(path, "not a legacy VTK file (no '# vtk DataFile' first line)");
  lines.next("its title line");
  const std::string encoding = toLower(trim(lines.next("ASCII or BINARY")));
  if (encoding != "ascii" && encoding != "binary")
    failLoad(path, "bad encoding " + quoteText(encoding) + " (ASCII or BINARY)");
  std::vector<std::string> w = lines.words("DATASET");
  if (w.size() < 2 || toLower(w[0]) != "dataset")
    failLoad(path, "no DATASET line after the encoding");
  if (toLower(w[1]) != "structured_points")
    failLoad(path, "DATASET " + quoteText(w[1]) +
                       " is not read (STRUCTURED_POINTS only: a regular grid of samples)");
  VolumeLayout layout;
  bool dimsGiven = false;
  for (;;) {
    w = lines.words("POINT_DATA");
    const std::string key = toLower(w[0]);
    if (key == "point_data") break;
    if (key == "cell_data" || key == "field")
      failLoad(path, w[0] + " before POINT_DATA is not read (point scalars only)");
    std::vector<double> v;
    if (w.size() != 4 || !parseDoubleList(w[1] + " " + w[2] + " " + w[3], v) || v.size() != 3)
      failLoad(path, "bad " + quoteText(w[0]) + " line (a keyword and three numbers)");
    if (key == "dimensions") {
      for (int a = 0; a < 3; ++a) {
        if (v[a] != std::floor(v[a]) || std::fabs(v[a]) > 1e15)
          failLoad(path, "DIMENSIONS must be whole numbers");
        layout.dims[a] = int64_t(v[a]);
      }
      dimsGiven = true;
    } else if (key == "spacing" || key == "aspect_ratio") {
      layout.spacing = glm::dvec3(v[0], v[1], v[2]);
    } else if (key == "origin") {
      layout.origin = glm::dvec3(v[0], v[1], v[2]);
    } else {
      failLoad(path, "unknown keyword " + quoteText(w[0]) + " in the STRUCTURED_POINTS header");
    }
  }
  if (!dimsGiven) failLoad(path, "no DIMENSIONS before POINT_DATA");
  int64_t points = 0;
  if (w.size() < 2 || !parseInt64(w[1], points)) failLoad(path, "bad POINT_DATA count");
  w = lines.words("SCALARS");
  // SCALARS of 1 to 4 components; COLOR_SCALARS of 1 to 4 values a point: bytes in binary
  // files and 0..1 in ASCII ones (how VTK writes an unsigned char image); VECTORS: three.
  // Several components a point are interleaved: --channel picks one.
  const std::string kind = toLower(w[0]);
  const bool colour = kind == "color_scalars", vectors = kind == "vectors";
  if (kind != "scalars" && !colour && !vectors)
    failLoad(path, quoteText(w[0]) + " point data is not read (SCALARS, COLOR_SCALARS, VECTORS)");
  if (w.size() < 3)
    failLoad(path, "bad " + w[0] + " line (" + w[0] +
                       (colour    ? " name values)"
                        : vectors ? " name type)"
                                  : " name type [components])"));
  int64_t components = vectors ? 3 : 1;
  if ((colour || w.size() > 3) && !vectors) {
    const std::string& count = colour ? w[2] : w[3];
    if (!parseInt64(count, components) || components < 1 || components > 4)
      failLoad(path, w[0] + " of " + quoteText(count) + " components are not read (1 to 4)");
  }
  const FileScalar type = scalarType(path, colour ? "unsigned_char" : w[2]);
  if (kind == "scalars") {
    w = lines.words("LOOKUP_TABLE");
    if (toLower(w[0]) != "lookup_table") failLoad(path, "no LOOKUP_TABLE line after SCALARS");
  }
  layout.type = type;
  const uint64_t voxels = dataByteCount(path, layout.dims, FileScalar::UInt8);
  if (points < 0 || uint64_t(points) != voxels)
    failLoad(path, "POINT_DATA " + std::to_string(points) + " is not the " +
                       std::to_string(voxels) + " points of DIMENSIONS");
  // Fits in memory, all components.
  const uint64_t bytes = componentDataByteCount(path, layout.dims, type, components);
  const uint64_t offset = lines.offset();
  std::vector<uint8_t> data;
  if (encoding == "binary") {
    layout.bigEndian = true;                    // as VTK writes it
    data = readFileRange(path, offset, bytes);  // checks the range
  } else {
    std::vector<double> values =
        readTextNumbers(path, offset, voxels * uint64_t(components), "ASCII data");
    if (colour)
      for (double& v : values) v *= 255.0;
    layout.bigEndian = hostIsBigEndian();
    data = encodeValues(values, type);
  }
  return makeVolume(path, layout,
                    pickComponent(path, std::move(data), components, channel, layout));
}

}  // namespace ewa
