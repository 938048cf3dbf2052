// Headerless raw volumes: parsing the --raw-* command-line options and reading the file.
#include <new>
#include <string>
#include <vector>

#include "io/file_bytes.h"
#include "io/load_failure.h"
#include "io/text_fields.h"
#include "io/volume_layout.h"
#include "io/volume_loader.h"

namespace ewa {

namespace {

[[noreturn]] void failOption(const std::string& option, const std::string& problem) {
  throw LoadError(oneLine(option + ": " + problem));
}

FileScalar rawType(const std::string& type) {
  static const std::pair<const char*, FileScalar> kAliases[] = {
      {"", FileScalar::UInt8},        {"char", FileScalar::Int8},
      {"uchar", FileScalar::UInt8},   {"short", FileScalar::Int16},
      {"ushort", FileScalar::UInt16}, {"int", FileScalar::Int32},
      {"uint", FileScalar::UInt32},   {"float", FileScalar::Float32},
      {"double", FileScalar::Float64}};
  const std::string t = toLower(trim(type));
  for (const auto& [name, scalar] : kAliases)
    if (t == name) return scalar;
  for (FileScalar scalar :
       {FileScalar::Int8, FileScalar::UInt8, FileScalar::Int16, FileScalar::UInt16,
        FileScalar::Int32, FileScalar::UInt32, FileScalar::Int64, FileScalar::UInt64,
        FileScalar::Float32, FileScalar::Float64})
    if (t == fileScalarName(scalar)) return scalar;
  failOption("--raw-type", "unknown type " + quoteText(type) +
                               " (expected int8, uint8, int16, uint16, int32, uint32, int64, "
                               "uint64, float32 or float64)");
}

}  // namespace

RawOptions parseRawOptions(const std::string& dims, const std::string& type,
                           const std::string& spacing, const std::string& endian) {
  RawOptions options;

  std::vector<int64_t> d;
  const std::string dimsText = trim(dims);
  if (dimsText.empty()) failOption("--raw-dims", "missing (expected X,Y,Z)");
  for (const std::string& word : splitWords(dimsText, ", \txX")) {
    int64_t v = 0;
    if (!parseInt64(word, v))
      failOption("--raw-dims", "expected X,Y,Z integers, not " + quoteText(dims));
    d.push_back(v);
  }
  if (d.size() != 3) failOption("--raw-dims", "expected three sizes X,Y,Z, not " + quoteText(dims));
  for (int64_t v : d) {
    if (v <= 0) failOption("--raw-dims", "sizes must be positive, not " + quoteText(dims));
  }
  options.dims = {d[0], d[1], d[2]};

  options.type = rawType(type);

  const std::string spacingText = trim(spacing);
  if (!spacingText.empty()) {
    std::vector<double> s;
    for (const std::string& word : splitWords(spacingText, ", \t")) {
      double v = 0.0;
      if (!parseDouble(word, v))
        failOption("--raw-spacing", "expected X,Y,Z numbers, not " + quoteText(spacing));
      s.push_back(v);
    }
    if (s.size() == 1) s = {s[0], s[0], s[0]};
    if (s.size() != 3)
      failOption("--raw-spacing", "expected X,Y,Z or one value, not " + quoteText(spacing));
    for (double v : s) {
      if (!(v > 0.0) || v > 1e300)
        failOption("--raw-spacing",
                   "spacing must be positive and finite, not " + quoteText(spacing));
    }
    options.spacing = {s[0], s[1], s[2]};
  }

  const std::string e = toLower(trim(endian));
  if (e.empty() || e == "little" || e == "le")
    options.bigEndian = false;
  else if (e == "big" || e == "be")
    options.bigEndian = true;
  else
    failOption("--raw-endian", "expected little or big, not " + quoteText(endian));
  return options;
}

Volume loadRawVolume(const std::string& path, const RawOptions& options) {
  VolumeLayout layout;
  layout.dims = options.dims;
  layout.spacing = options.spacing;
  layout.type = options.type;
  layout.bigEndian = options.bigEndian;
  try {
    const uint64_t total = dataByteCount(path, layout.dims, layout.type);
    std::vector<uint8_t> bytes = readFileRange(path, 0, total);
    return makeVolume(path, layout, std::move(bytes));
  } catch (const std::bad_alloc&) {
    failLoad(path, "out of memory");
  }
}

}  // namespace ewa
