// MetaImage (.mhd header + data file, or .mha with LOCAL data), raw or zlib-compressed.
#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/decompress.h"
#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/region_read.h"
#include "io/text_fields.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

constexpr uint64_t kMaxHeaderBytes = 16u << 20;

// Offset just past the ElementDataFile line (always the last header line), or npos.
size_t headerEnd(std::string_view text) {
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) return std::string_view::npos;
    const std::string_view line = trimView(text.substr(pos, eol - pos));
    if (normalizedKey(line.substr(0, 15)) == "elementdatafile") return eol + 1;
    pos = eol + 1;
  }
  return std::string_view::npos;
}

FileScalar parseElementType(const std::string& path, const std::string& value) {
  // MetaIO's sizes: MET_LONG is 4 bytes, MET_LONG_LONG 8.
  static const std::pair<const char*, FileScalar> kTypes[] = {
      {"MET_UCHAR", FileScalar::UInt8},     {"MET_CHAR", FileScalar::Int8},
      {"MET_SHORT", FileScalar::Int16},     {"MET_USHORT", FileScalar::UInt16},
      {"MET_INT", FileScalar::Int32},       {"MET_UINT", FileScalar::UInt32},
      {"MET_LONG", FileScalar::Int32},      {"MET_ULONG", FileScalar::UInt32},
      {"MET_LONG_LONG", FileScalar::Int64}, {"MET_ULONG_LONG", FileScalar::UInt64},
      {"MET_FLOAT", FileScalar::Float32},   {"MET_DOUBLE", FileScalar::Float64}};
  for (const auto& [name, type] : kTypes)
    if (value == name) return type;
  if (value.compare(0, 4, "MET_") == 0)
    failLoad(path, "unsupported ElementType " + quoteText(value) + " (scalar numbers only)");
  failLoad(path, "unknown ElementType " + quoteText(value));
}

bool parseBool(const std::string& path, const std::string& key, const std::string& value) {
  const std::string v = toLower(value);
  if (v == "true" || v == "1") return true;
  if (v == "false" || v == "0") return false;
  failLoad(path, "bad " + key + " value " + quoteText(value));
}

// Reads `count` numbers of `key` into `out` (the rest keep their default).
void parseAxes(const std::string& path, const std::string& key, const std::string& value,
               size_t count, double* out) {
  std::vector<double> v;
  if (!parseDoubleList(value, v) || v.size() != count)
    failLoad(path, "bad " + key + " " + quoteText(value) + " (need " + std::to_string(count) +
                       " numbers)");
  for (size_t a = 0; a < count; ++a) out[a] = v[a];
}

// True for an AnatomicalOrientation that names one side of each patient axis ("RAI", "LPS"):
// ITK writes "??" or "???" where it knows none, which says nothing about the axes.
bool anatomicalCode(const std::string* value) {
  if (!value) return false;
  const std::string code = toLower(trim(*value));
  if (code.size() != 3) return false;
  bool seen[3] = {false, false, false};
  for (const char c : code) {
    const int axis = (c == 'r' || c == 'l')   ? 0
                     : (c == 'a' || c == 'p') ? 1
                     : (c == 's' || c == 'i') ? 2
                                              : -1;
    if (axis < 0 || seen[axis]) return false;
    seen[axis] = true;
  }
  return true;
}

// What the header says: the layout, where the data are and how they are stored.
struct MetaImageHeader {
  VolumeLayout layout;
  std::string dataPath;
  bool local = false, compressed = false;
  int64_t channels = 1, headerSize = 0;
  uint64_t dataOffset = 0;  // LOCAL: where the data start after the header
  std::optional<std::string> compressedDataSize;
};

MetaImageHeader readMetaImageHeader(const std::string& path, DataFileScope scope) {
  const uint64_t fileSize = regularFileSize(path);
  const std::string text = readFilePrefix(path, kMaxHeaderBytes, [](std::string_view t) {
    return headerEnd(t) != std::string_view::npos;
  });

  // Fields by normalized key; ElementDataFile ends the header.
  std::map<std::string, std::string> fields;
  uint64_t dataOffset = 0;
  size_t pos = 0;
  while (pos < text.size() && !fields.count("elementdatafile")) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) {
      if (text.size() < fileSize) failLoad(path, "header is longer than 16 MiB");
      eol = text.size();
    }
    const std::string_view line = trimView(std::string_view(text).substr(pos, eol - pos));
    pos = eol + 1;
    dataOffset = std::min<uint64_t>(pos, text.size());
    if (line.empty()) continue;
    const size_t eq = line.find('=');
    if (eq == std::string_view::npos || eq == 0)
      failLoad(path, "malformed header line " + quoteText(line));
    fields[normalizedKey(line.substr(0, eq))] = trim(line.substr(eq + 1));
  }
  auto field = [&](const char* key) -> const std::string* {
    const auto it = fields.find(key);
    return it == fields.end() ? nullptr : &it->second;
  };
  if (!field("elementdatafile")) failLoad(path, "not a MetaImage header (no ElementDataFile line)");
  if (const std::string* v = field("objecttype"); v && toLower(*v) != "image")
    failLoad(path, "unsupported ObjectType " + quoteText(*v) + " (need Image)");

  const std::string* ndimsText = field("ndims");
  if (!ndimsText) failLoad(path, "missing NDims");
  int64_t ndims = 0;
  if (!parseInt64(*ndimsText, ndims) || ndims < 1 || ndims > 3)
    failLoad(path, "unsupported NDims " + quoteText(*ndimsText) + " (need 1 to 3)");
  const auto n = static_cast<size_t>(ndims);

  VolumeLayout layout;
  layout.dims = {1, 1, 1};
  const std::string* dimText = field("dimsize");
  if (!dimText) failLoad(path, "missing DimSize");
  std::vector<int64_t> dims;
  if (!parseInt64List(*dimText, dims) || dims.size() != n)
    failLoad(path, "bad DimSize " + quoteText(*dimText));
  for (size_t a = 0; a < n; ++a) layout.dims[a] = dims[a];
  const std::string* typeText = field("elementtype");
  if (!typeText) failLoad(path, "missing ElementType");
  layout.type = parseElementType(path, *typeText);

  // ElementSpacing is the grid step; ElementSize (voxel extent) is only a fallback.
  for (const char* key : {"elementspacing", "elementsize"}) {
    if (const std::string* v = field(key)) {
      parseAxes(path, key, *v, n, &layout.spacing[0]);
      break;
    }
  }
  for (const char* key : {"offset", "position", "origin"}) {
    if (const std::string* v = field(key)) {
      parseAxes(path, key, *v, n, &layout.origin[0]);
      break;
    }
  }
  // TransformMatrix lists the direction of each axis in turn (ITK's convention, LPS world).
  for (const char* key : {"transformmatrix", "rotation", "orientation"}) {
    if (const std::string* v = field(key)) {
      double m[9] = {};
      parseAxes(path, key, *v, n * n, m);
      for (size_t a = 0; a < n; ++a)
        for (size_t c = 0; c < n; ++c) layout.direction[int(a)][int(c)] = m[a * n + c];
      break;
    }
  }
  layout.patientFrame = anatomicalCode(field("anatomicalorientation"));
  int64_t channels = 1;  // interleaved in each voxel (colour, vectors)
  if (const std::string* v = field("elementnumberofchannels"); v && !parseInt64(trim(*v), channels))
    failLoad(path, "bad ElementNumberOfChannels " + quoteText(*v));
  if (const std::string* v = field("binarydata"); v && !parseBool(path, "BinaryData", *v))
    failLoad(path, "unsupported text (BinaryData = False) data");
  for (const char* key : {"binarydatabyteordermsb", "elementbyteordermsb"}) {
    if (const std::string* v = field(key)) layout.bigEndian = parseBool(path, key, *v);
  }
  const std::string* compressedText = field("compresseddata");
  const bool compressed = compressedText && parseBool(path, "CompressedData", *compressedText);
  int64_t headerSize = 0;
  if (const std::string* v = field("headersize");
      v && (!parseInt64(*v, headerSize) || headerSize < -1))
    failLoad(path, "bad HeaderSize " + quoteText(*v));

  const std::string& dataName = *field("elementdatafile");
  if (dataName.empty()) failLoad(path, "empty ElementDataFile");
  const bool local = toLower(dataName) == "local";
  if (!local && (splitWords(dataName)[0] == "LIST" || dataName.find('%') != std::string::npos))
    failLoad(path,
             "unsupported ElementDataFile " + quoteText(dataName) + " (need one file or LOCAL)");
  const std::string dataPath = local ? path : siblingPath(path, dataName);
  checkDataFileScope(path, dataPath, scope);
  layout.sourceFiles.push_back(dataPath);

  MetaImageHeader h;
  h.layout = std::move(layout);
  h.dataPath = dataPath;
  h.local = local;
  h.compressed = compressed;
  h.channels = channels;
  h.headerSize = headerSize;
  h.dataOffset = dataOffset;
  if (const std::string* v = field("compresseddatasize")) h.compressedDataSize = *v;
  return h;
}

}  // namespace

Volume loadMetaImage(const std::string& path, int channel, DataFileScope scope) {
  MetaImageHeader h = readMetaImageHeader(path, scope);
  VolumeLayout& layout = h.layout;
  const std::string& dataPath = h.dataPath;
  const bool local = h.local, compressed = h.compressed;
  const int64_t channels = h.channels, headerSize = h.headerSize;
  const uint64_t dataOffset = h.dataOffset;
  const uint64_t total = componentDataByteCount(path, layout.dims, layout.type, channels);
  const uint64_t dataFileSize = regularFileSize(dataPath);
  uint64_t start = local ? dataOffset : static_cast<uint64_t>(std::max<int64_t>(headerSize, 0));
  std::vector<uint8_t> bytes;
  if (compressed) {
    if (!local && headerSize == -1)
      failLoad(path, "HeaderSize -1 cannot be used with compressed data");
    if (start > dataFileSize) failLoad(dataPath, "HeaderSize is past the end of the file");
    uint64_t packedSize = dataFileSize - start;
    if (const std::optional<std::string>& v = h.compressedDataSize) {
      int64_t s = 0;
      if (!parseInt64(*v, s) || s < 0) failLoad(path, "bad CompressedDataSize " + quoteText(*v));
      if (static_cast<uint64_t>(s) > packedSize) {
        failLoad(dataPath, "CompressedDataSize " + std::to_string(s) + " exceeds the " +
                               std::to_string(packedSize) + " bytes present (truncated file?)");
      }
      packedSize = static_cast<uint64_t>(s);
    }
    const std::vector<uint8_t> packed =
        readFileRange(dataPath, start, packedSize, "compressed data");
    bytes = inflateExact(dataPath, packed.data(), packed.size(), total, "compressed data");
  } else {
    if (!local && headerSize == -1) {
      // HeaderSize -1: the data are the last bytes of the file.
      if (dataFileSize < total)
        failLoad(dataPath, "file has " + std::to_string(dataFileSize) + " bytes, fewer than the " +
                               std::to_string(total) + " bytes of data");
      start = dataFileSize - total;
    }
    bytes = readFileRange(dataPath, start, total);
  }
  bytes = pickComponent(path, std::move(bytes), channels, channel, layout);
  return makeVolume(path, layout, std::move(bytes));
}

std::optional<RawPlacement> metaImageRawPlacement(const std::string& path, DataFileScope scope) {
  const MetaImageHeader h = readMetaImageHeader(path, scope);
  if (h.compressed || h.channels != 1) return std::nullopt;
  // The whole need not fit this process's memory: a box of it is read.
  const uint64_t total = wholeDataBytes(path, h.layout.dims, h.layout.type);
  RawPlacement p;
  p.layout = h.layout;
  p.file = h.dataPath;
  const uint64_t size = regularFileSize(h.dataPath);
  if (h.local) {
    p.offset = h.dataOffset;
  } else if (h.headerSize == -1) {
    if (size < total) return std::nullopt;  // the whole-file reader says why
    p.offset = size - total;
  } else {
    p.offset = uint64_t(h.headerSize);
  }
  if (p.offset > size || size - p.offset < total) return std::nullopt;
  return p;
}

}  // namespace ewa
