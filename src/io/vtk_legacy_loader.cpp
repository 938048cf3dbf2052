// Legacy VTK files (.vtk) of STRUCTURED_POINTS: point scalars, ASCII or big-endian binary.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "io/byte_order.h"
#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/text_fields.h"
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

struct ScalarKind {
  FileScalar stored = FileScalar::Float32;  // what the volume keeps
  size_t bytes = 4;                         // of one value in the file
  bool convert = false;                     // int, unsigned_int, long, double: to float32
  bool isSigned = true, isReal = true;
};

ScalarKind scalarKind(const std::string& path, const std::string& name) {
  const std::string t = toLower(name);
  if (t == "unsigned_char") return {FileScalar::UInt8, 1, false, false, false};
  if (t == "char" || t == "signed_char") return {FileScalar::Int8, 1, false, true, false};
  if (t == "unsigned_short") return {FileScalar::UInt16, 2, false, false, false};
  if (t == "short") return {FileScalar::Int16, 2, false, true, false};
  if (t == "float") return {FileScalar::Float32, 4, false, true, true};
  if (t == "int") return {FileScalar::Float32, 4, true, true, false};
  if (t == "unsigned_int") return {FileScalar::Float32, 4, true, false, false};
  if (t == "long" || t == "vtktypeint64") return {FileScalar::Float32, 8, true, true, false};
  if (t == "unsigned_long" || t == "vtktypeuint64")
    return {FileScalar::Float32, 8, true, false, false};
  if (t == "double") return {FileScalar::Float32, 8, true, true, true};
  failLoad(path, "SCALARS of type " + quoteText(name) +
                     " are not read (unsigned_char, char, short, unsigned_short, int, "
                     "unsigned_int, long, unsigned_long, float, double)");
}

// One big-endian value of `kind` at `p` as a double.
double binaryValue(const ScalarKind& kind, const uint8_t* p) {
  uint64_t bits = 0;
  for (size_t i = 0; i < kind.bytes; ++i) bits = (bits << 8) | p[i];
  if (kind.isReal) {
    if (kind.bytes == 8) {
      double d;
      std::memcpy(&d, &bits, 8);
      return d;
    }
    const auto u = uint32_t(bits);
    float f;
    std::memcpy(&f, &u, 4);
    return f;
  }
  if (!kind.isSigned) return double(bits);
  const int shift = int(64 - 8 * kind.bytes);
  return double(int64_t(bits << shift) >> shift);
}

}  // namespace

Volume loadVtkLegacy(const std::string& path) {
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
  // COLOR_SCALARS of one value a point: gray, bytes in binary files and 0..1 in ASCII ones
  // (how VTK writes an unsigned char image).
  const bool colour = toLower(w[0]) == "color_scalars";
  if (toLower(w[0]) != "scalars" && !colour)
    failLoad(path, quoteText(w[0]) + " point data is not read (SCALARS only)");
  if (colour ? w.size() != 3 || w[2] != "1" : w.size() < 3)
    failLoad(path, colour ? "COLOR_SCALARS of other than 1 value a point are not read"
                          : "bad SCALARS line (SCALARS name type [components])");
  if (!colour && w.size() > 3 && w[3] != "1")
    failLoad(path, "SCALARS of " + quoteText(w[3]) + " components are not read (1 only)");
  const std::string typeName = colour ? "unsigned_char" : w[2];
  const ScalarKind kind = scalarKind(path, typeName);
  if (!colour) {
    w = lines.words("LOOKUP_TABLE");
    if (toLower(w[0]) != "lookup_table") failLoad(path, "no LOOKUP_TABLE line after SCALARS");
  }
  layout.type = kind.stored;
  const uint64_t voxels = dataByteCount(path, layout.dims, FileScalar::UInt8);
  if (points < 0 || uint64_t(points) != voxels)
    failLoad(path, "POINT_DATA " + std::to_string(points) + " is not the " +
                       std::to_string(voxels) + " points of DIMENSIONS");
  dataByteCount(path, layout.dims, kind.stored);  // the volume fits in memory
  const uint64_t offset = lines.offset();
  if (encoding == "binary") {
    const uint64_t need = voxels * kind.bytes;  // no overflow: checked as float32 above x2
    const std::vector<uint8_t> data = readFileRange(path, offset, need);  // checks the range
    if (!kind.convert && kind.bytes > 1) {  // big-endian as VTK writes it
      layout.bigEndian = true;
      return makeVolume(path, layout, data);
    }
    if (!kind.convert) return makeVolume(path, layout, data);
    std::vector<uint8_t> floats(size_t(voxels) * 4);
    for (size_t i = 0; i < size_t(voxels); ++i) {
      const auto f = float(binaryValue(kind, &data[i * kind.bytes]));
      std::memcpy(&floats[4 * i], &f, 4);
    }
    layout.notes.push_back("SCALARS of type " + quoteText(typeName) + " converted to float32");
    return makeVolume(path, layout, std::move(floats));
  }
  {
    // ASCII: each number takes at least one character and a separator: bound the count first.
    if (voxels > (size - offset + 1) / 2)
      failLoad(path, "the ASCII data cannot hold " + std::to_string(voxels) +
                         " numbers (truncated file or wrong sizes?)");
    std::vector<uint8_t> text = readFileRange(path, offset, size - offset);
    text.push_back(0);
    std::vector<double> values(static_cast<size_t>(voxels));
    const char* p = reinterpret_cast<const char*>(text.data());
    for (size_t i = 0; i < values.size(); ++i) {
      char* end = nullptr;
      values[i] = std::strtod(p, &end) * (colour ? 255.0 : 1.0);
      if (end == p)
        failLoad(path, "ASCII data has " + std::to_string(i) + " numbers, not " +
                           std::to_string(voxels) + " (truncated file or not a number)");
      p = end;
    }
    if (kind.convert)
      layout.notes.push_back("SCALARS of type " + quoteText(typeName) + " converted to float32");
    return makeVolume(path, layout, encodeValues(values, kind.stored));
  }
}

}  // namespace ewa
