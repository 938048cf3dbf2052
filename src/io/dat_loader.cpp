// Voreen / Inviwo ".dat" volumes: a "Key: value" text header naming a raw data file.
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/text_fields.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

constexpr uint64_t kMaxHeaderBytes = 1u << 20;

FileScalar parseFormat(const std::string& path, const std::string& value) {
  const std::string f = toLower(value);
  if (f == "uchar" || f == "uint8") return FileScalar::UInt8;
  if (f == "char" || f == "int8") return FileScalar::Int8;
  if (f == "ushort" || f == "uint16" || f == "ushort_12" || f == "uint12")
    return FileScalar::UInt16;
  if (f == "short" || f == "int16") return FileScalar::Int16;
  if (f == "float" || f == "float32") return FileScalar::Float32;
  for (const char* n : {"uint", "int", "uint32", "int32", "uint64", "int64", "ulong", "long",
                        "double", "float64", "float16", "half"}) {
    if (f == n) {
      failLoad(path, "unsupported Format " + quoteText(value) +
                         " (supported: UCHAR, CHAR, USHORT, SHORT, FLOAT)");
    }
  }
  failLoad(path, "unknown Format " + quoteText(value));
}

// The first of `keys` present in `fields`, or null.
const std::string* findField(const std::map<std::string, std::string>& fields,
                             std::initializer_list<const char*> keys) {
  for (const char* k : keys) {
    const auto it = fields.find(k);
    if (it != fields.end()) return &it->second;
  }
  return nullptr;
}

}  // namespace

Volume loadDat(const std::string& path, DataFileScope scope) {
  const uint64_t size = regularFileSize(path);
  if (size > kMaxHeaderBytes) failLoad(path, "too large for a .dat text header");
  const std::vector<uint8_t> raw = readFileRange(path, 0, size, "header");
  const std::string text(raw.begin(), raw.end());
  if (text.find('\0') != std::string::npos)
    failLoad(path, "not a text header (contains NUL bytes)");

  std::map<std::string, std::string> fields;
  for (const std::string& rawLine : splitWords(text, "\n")) {
    const std::string_view line = trimView(rawLine);
    if (line.empty() || line[0] == '#') continue;
    const size_t colon = line.find(':');
    if (colon == std::string_view::npos || colon == 0)
      failLoad(path, "malformed header line " + quoteText(line) + " (expected Key: value)");
    fields[normalizedKey(line.substr(0, colon))] = trim(line.substr(colon + 1));
  }

  const std::string* fileName = findField(fields, {"objectfilename", "rawfile"});
  if (!fileName || fileName->empty()) failLoad(path, "missing ObjectFileName (or RawFile)");
  const std::string* resolution = findField(fields, {"resolution", "dimensions"});
  if (!resolution) failLoad(path, "missing Resolution (or Dimensions)");
  const std::string* format = findField(fields, {"format"});
  if (!format) failLoad(path, "missing Format");

  VolumeLayout layout;
  layout.type = parseFormat(path, *format);
  std::vector<int64_t> dims;
  if (!parseInt64List(*resolution, dims) || dims.size() < 2 || dims.size() > 3)
    failLoad(path, "bad Resolution " + quoteText(*resolution));
  layout.dims = {dims[0], dims[1], dims.size() == 3 ? dims[2] : 1};
  if (const std::string* v = findField(fields, {"slicethickness", "spacing"})) {
    std::vector<double> s;
    if (!parseDoubleList(*v, s) || s.size() != dims.size())
      failLoad(path, "bad SliceThickness " + quoteText(*v));
    for (size_t a = 0; a < s.size(); ++a) layout.spacing[a] = s[a];
  }
  if (const std::string* v = findField(fields, {"origin", "offset"})) {
    std::vector<double> o;
    if (!parseDoubleList(*v, o) || o.size() != dims.size())
      failLoad(path, "bad Offset " + quoteText(*v));
    for (size_t a = 0; a < o.size(); ++a) layout.origin[a] = o[a];
  }
  if (const std::string* v = findField(fields, {"byteorder", "endianness", "endian"})) {
    const std::string e = toLower(*v);
    if (e == "bigendian" || e == "big")
      layout.bigEndian = true;
    else if (e == "littleendian" || e == "little")
      layout.bigEndian = false;
    else
      failLoad(path, "bad ByteOrder " + quoteText(*v) + " (need LittleEndian or BigEndian)");
  }
  int64_t skip = 0;
  if (const std::string* v = findField(fields, {"byteoffset", "headerskip"})) {
    if (!parseInt64(*v, skip) || skip < 0) failLoad(path, "bad ByteOffset " + quoteText(*v));
  }

  const uint64_t total = dataByteCount(path, layout.dims, layout.type);
  const std::string dataPath = siblingPath(path, *fileName);
  checkDataFileScope(path, dataPath, scope);
  layout.sourceFiles.push_back(dataPath);
  std::vector<uint8_t> bytes = readFileRange(dataPath, static_cast<uint64_t>(skip), total);
  return makeVolume(path, layout, std::move(bytes));
}

}  // namespace ewa
