// NRRD header parsing: fields, type and encoding names, data file forms (single, LIST, pattern).
#include "io/nrrd_header.h"

#include <cmath>
#include <cstdlib>
#include <string_view>

#include "io/file_bytes.h"
#include "io/length_unit.h"
#include "io/load_failure.h"
#include "io/text_fields.h"

namespace ewa {

namespace {

constexpr uint64_t kMaxHeaderBytes = 16u << 20;
constexpr int64_t kMaxDataFiles = 1 << 20;

// Offset just past the blank line that ends an attached header, or npos.
size_t headerEnd(std::string_view text) {
  for (size_t i = text.find('\n'); i != std::string_view::npos; i = text.find('\n', i + 1)) {
    size_t j = i + 1;
    if (j < text.size() && text[j] == '\r') ++j;
    if (j < text.size() && text[j] == '\n') return j + 1;
  }
  return std::string_view::npos;
}

FileScalar parseType(const std::string& path, const std::string& value) {
  struct Names {
    FileScalar type;
    std::vector<const char*> names;
  };
  // The type names NRRD's format definition allows, lowercased, words joined by one space.
  static const std::vector<Names> kTypes = {
      {FileScalar::UInt8, {"uchar", "unsigned char", "uint8", "uint8_t"}},
      {FileScalar::Int8, {"signed char", "int8", "int8_t"}},
      {FileScalar::Int16,
       {"short", "short int", "signed short", "signed short int", "int16", "int16_t"}},
      {FileScalar::UInt16,
       {"ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t"}},
      {FileScalar::Int32, {"int", "signed int", "int32", "int32_t"}},
      {FileScalar::UInt32, {"uint", "unsigned int", "uint32", "uint32_t"}},
      {FileScalar::Int64,
       {"longlong", "long long", "long long int", "signed long long", "signed long long int",
        "int64", "int64_t"}},
      {FileScalar::UInt64,
       {"ulonglong", "unsigned long long", "unsigned long long int", "uint64", "uint64_t"}},
      {FileScalar::Float32, {"float"}},
      {FileScalar::Float64, {"double"}}};
  std::string name;
  for (const std::string& w : splitWords(toLower(value))) name += (name.empty() ? "" : " ") + w;
  for (const Names& t : kTypes)
    for (const char* n : t.names)
      if (name == n) return t.type;
  if (name == "block") failLoad(path, "unsupported type 'block' (numbers only)");
  failLoad(path, "unknown type " + quoteText(value));
}

NrrdEncoding parseEncoding(const std::string& path, const std::string& value) {
  const std::string e = toLower(value);
  if (e == "raw") return NrrdEncoding::Raw;
  if (e == "gzip" || e == "gz") return NrrdEncoding::Gzip;
  if (e == "bzip2" || e == "bz2") return NrrdEncoding::Bzip2;
  if (e == "ascii" || e == "text" || e == "txt") return NrrdEncoding::Ascii;
  if (e == "hex") return NrrdEncoding::Hex;
  if (e == "zstd" || e == "zrl")
    failLoad(path, "unsupported encoding " + quoteText(value) +
                       " (supported: raw, gzip, bzip2, ascii, hex)");
  failLoad(path, "unknown encoding " + quoteText(value));
}

// Parses "(a,b,c)" vectors and "none" entries of "space directions" / "space origin".
// A "none" entry is returned as an empty vector.
std::vector<std::vector<double>> parseVectors(const std::string& path, const std::string& field,
                                              std::string_view text) {
  std::vector<std::vector<double>> vectors;
  size_t i = 0;
  while (true) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    if (i >= text.size()) break;
    if (text.substr(i, 4) == "none") {
      vectors.emplace_back();
      i += 4;
      continue;
    }
    const size_t close = text.find(')', i);
    if (text[i] != '(' || close == std::string_view::npos)
      failLoad(path, "bad " + field + " " + quoteText(text));
    std::vector<double> v;
    for (const std::string& part : splitWords(text.substr(i + 1, close - i - 1), ",")) {
      double d = 0.0;
      if (!parseDouble(part, d)) failLoad(path, "bad " + field + " " + quoteText(text));
      v.push_back(d);
    }
    if (v.empty() || v.size() > 3) failLoad(path, "bad " + field + " " + quoteText(text));
    vectors.push_back(std::move(v));
    i = close + 1;
  }
  return vectors;
}

int64_t parseIntField(const std::string& path, const std::string& field, const std::string& value) {
  int64_t v = 0;
  if (!parseInt64(value, v)) failLoad(path, "bad " + field + " " + quoteText(value));
  return v;
}

// "LIST [subdim]" and "<pattern> <min> <max> <step> [<subdim>]" forms; else a single file name.
void parseDataFile(const std::string& path, const std::string& value, NrrdHeader& h,
                   bool& listFollows) {
  const std::vector<std::string> words = splitWords(value);
  if (words.empty()) failLoad(path, "empty data file field");
  auto subdimOf = [&](const std::string& word) {
    const int64_t s = parseIntField(path, "data file subdimension", word);
    if (s < 1 || s > 3) failLoad(path, "bad data file subdimension " + quoteText(word));
    return static_cast<int>(s);
  };
  if (words[0] == "LIST" && words.size() <= 2) {
    if (words.size() == 2) h.subdim = subdimOf(words[1]);
    listFollows = true;
    return;
  }
  int64_t nums[3];
  const bool pattern = words[0].find('%') != std::string::npos &&
                       (words.size() == 4 || words.size() == 5) && parseInt64(words[1], nums[0]) &&
                       parseInt64(words[2], nums[1]) && parseInt64(words[3], nums[2]);
  if (!pattern) {
    h.dataFiles.push_back(siblingPath(path, value));
    return;
  }
  const int64_t first = nums[0], last = nums[1], step = nums[2];
  if (words.size() == 5) h.subdim = subdimOf(words[4]);
  if (step == 0 || (step > 0 && last < first) || (step < 0 && last > first))
    failLoad(path, "bad data file range " + quoteText(value));
  // |last - first| may overflow int64; do it in wider arithmetic.
  const __int128 count = (static_cast<__int128>(last) - first) / step + 1;
  if (count > kMaxDataFiles) failLoad(path, "data file pattern names too many files");
  for (int64_t n = 0; n < static_cast<int64_t>(count); ++n) {
    const int64_t index = static_cast<int64_t>(first + static_cast<__int128>(n) * step);
    h.dataFiles.push_back(siblingPath(path, formatNrrdPattern(path, words[0], index)));
  }
}

// Anatomical spaces become LPS (the viewer's world): RAS and LAS flip the axes that differ.
void applyNrrdSpace(const std::string& space, VolumeLayout& layout) {
  glm::dvec3 sign(1.0);
  if (space == "left-posterior-superior" || space == "lps") {
  } else if (space == "right-anterior-superior" || space == "ras") {
    sign = {-1.0, -1.0, 1.0};
  } else if (space == "left-anterior-superior" || space == "las") {
    sign = {1.0, -1.0, 1.0};
  } else {
    return;  // scanner or plain 3D spaces: no patient frame
  }
  layout.patientFrame = true;
  layout.origin *= sign;
  for (int a = 0; a < 3; ++a) layout.direction[a] *= sign;
}

// The one unit of `"mm" "mm" "mm"` (space units, or units per axis; spellings of one unit are
// one), or "" when they differ, are missing or are not a unit.
std::string quotedUnit(const std::string& value) {
  std::vector<std::string> units;
  for (size_t open = value.find('"'); open != std::string::npos;) {
    const size_t close = value.find('"', open + 1);
    if (close == std::string::npos) return "";
    units.push_back(value.substr(open + 1, close - open - 1));
    open = value.find('"', close + 1);
  }
  if (units.empty()) return "";
  const std::string unit = lengthUnitName(units[0]);
  for (const std::string& u : units)
    if (lengthUnitName(u) != unit) return "";
  return unit;
}

}  // namespace

std::string formatNrrdPattern(const std::string& path, const std::string& pattern, int64_t index) {
  std::string out;
  int conversions = 0;
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      out.push_back(pattern[i]);
      continue;
    }
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      out.push_back('%');
      ++i;
      continue;
    }
    bool left = false, zero = false, plus = false, space = false;
    size_t j = i + 1;
    for (;
         j < pattern.size() && std::string_view("-0+ ").find(pattern[j]) != std::string_view::npos;
         ++j) {
      left |= pattern[j] == '-';
      zero |= pattern[j] == '0';
      plus |= pattern[j] == '+';
      space |= pattern[j] == ' ';
    }
    size_t width = 0;
    for (; j < pattern.size() && pattern[j] >= '0' && pattern[j] <= '9'; ++j) {
      width = width * 10 + static_cast<size_t>(pattern[j] - '0');
      if (width > 64) failLoad(path, "data file pattern width is too large");
    }
    if (j >= pattern.size() || (pattern[j] != 'd' && pattern[j] != 'i' && pattern[j] != 'u') ||
        ++conversions > 1) {
      failLoad(path, "unsupported data file pattern " + quoteText(pattern) +
                         " (expected one %d conversion)");
    }
    std::string digits = std::to_string(index);
    std::string sign;
    if (digits[0] == '-') {
      sign = "-";
      digits.erase(0, 1);
    } else if (plus) {
      sign = "+";
    } else if (space) {
      sign = " ";
    }
    std::string number = sign + digits;
    if (number.size() < width) {
      const size_t pad = width - number.size();
      if (left)
        number += std::string(pad, ' ');
      else if (zero)
        number = sign + std::string(pad, '0') + digits;
      else
        number = std::string(pad, ' ') + number;
    }
    out += number;
    i = j;
  }
  if (conversions != 1) failLoad(path, "data file pattern " + quoteText(pattern) + " has no %d");
  return out;
}

NrrdHeader parseNrrdHeader(const std::string& path) {
  const uint64_t fileSize = regularFileSize(path);
  // Stop reading at the header end, or at once when the magic shows it is not NRRD.
  const std::string text = readFilePrefix(path, kMaxHeaderBytes, [](std::string_view t) {
    return t.compare(0, 7, "NRRD000") != 0 || headerEnd(t) != std::string_view::npos;
  });
  if (text.size() < 8 || text.compare(0, 7, "NRRD000") != 0 || text[7] < '1' || text[7] > '9') {
    failLoad(path, "not a NRRD file (it does not start with NRRD000x)");
  }

  NrrdHeader h;
  bool haveType = false, haveEncoding = false, listFollows = false, ended = false;
  std::vector<int64_t> sizes;
  std::vector<double> spacings;
  std::vector<std::vector<double>> directions, origin;
  std::vector<std::string> kinds;
  std::string space;
  size_t pos = text.find('\n');
  pos = pos == std::string::npos ? text.size() : pos + 1;
  while (pos < text.size()) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) {
      if (text.size() < fileSize) failLoad(path, "header is longer than 16 MiB");
      eol = text.size();
    }
    std::string_view line(text.data() + pos, eol - pos);
    pos = eol + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty()) {
      ended = true;
      h.attachedOffset = pos;
      break;
    }
    if (listFollows) {
      if (h.dataFiles.size() >= static_cast<size_t>(kMaxDataFiles))
        failLoad(path, "too many data files");
      h.dataFiles.push_back(siblingPath(path, trim(line)));
      continue;
    }
    if (line[0] == '#') continue;
    const size_t colon = line.find(':');
    if (colon == std::string_view::npos || colon == 0)
      failLoad(path, "malformed header line " + quoteText(line));
    if (colon + 1 < line.size() && line[colon + 1] == '=') continue;  // key/value pair
    const std::string key = normalizedKey(line.substr(0, colon));
    const std::string value = trim(line.substr(colon + 1));
    if (key == "dimension") {
      const int64_t d = parseIntField(path, "dimension", value);
      if (d < 1 || d > 4)
        failLoad(path, "unsupported dimension " + quoteText(value) + " (need 1 to 4)");
      h.dimension = static_cast<int>(d);
    } else if (key == "type") {
      h.layout.type = parseType(path, value);
      haveType = true;
    } else if (key == "encoding") {
      h.encoding = parseEncoding(path, value);
      haveEncoding = true;
    } else if (key == "endian") {
      const std::string e = toLower(value);
      if (e != "little" && e != "big") failLoad(path, "bad endian " + quoteText(value));
      h.layout.bigEndian = e == "big";
    } else if (key == "kinds") {
      kinds = splitWords(toLower(value));
    } else if (key == "sizes") {
      if (!parseInt64List(value, sizes)) failLoad(path, "bad sizes " + quoteText(value));
    } else if (key == "spacings") {
      if (!parseDoubleList(value, spacings)) failLoad(path, "bad spacings " + quoteText(value));
    } else if (key == "spacedirections") {
      directions = parseVectors(path, "space directions", value);
    } else if (key == "space") {
      space = toLower(value);
    } else if (key == "spaceunits" || (key == "units" && h.layout.unit.empty())) {
      h.layout.unit = quotedUnit(value);
    } else if (key == "spaceorigin") {
      origin = parseVectors(path, "space origin", value);
      if (origin.size() != 1 || origin[0].empty())
        failLoad(path, "bad space origin " + quoteText(value));
    } else if (key == "byteskip") {
      h.byteSkip = parseIntField(path, "byte skip", value);
      if (h.byteSkip < -1) failLoad(path, "byte skip must be -1 or more, not " + quoteText(value));
    } else if (key == "lineskip") {
      h.lineSkip = parseIntField(path, "line skip", value);
      if (h.lineSkip < 0) failLoad(path, "line skip must not be negative");
    } else if (key == "datafile") {
      parseDataFile(path, value, h, listFollows);
    }
    // Other fields (content, centers, ...) do not affect loading; kinds matter in 4D only.
  }
  if (!ended) {
    if (h.dataFiles.empty() && !listFollows)
      failLoad(path, "no data file field, and no blank line before attached data");
    h.attachedOffset = text.size();
  }

  if (h.dimension == 0) failLoad(path, "missing dimension field");
  if (!haveType) failLoad(path, "missing type field");
  if (!haveEncoding) failLoad(path, "missing encoding field");
  if (sizes.empty()) failLoad(path, "missing sizes field");
  const auto dim = static_cast<size_t>(h.dimension);
  if (sizes.size() != dim)
    failLoad(path, "sizes has " + std::to_string(sizes.size()) + " values but dimension is " +
                       std::to_string(dim));
  if (!spacings.empty() && spacings.size() != dim)
    failLoad(path, "spacings count does not match dimension");
  if (!directions.empty() && directions.size() != dim)
    failLoad(path, "space directions count does not match dimension");
  if (listFollows && h.dataFiles.empty()) failLoad(path, "data file LIST names no files");
  if (h.encoding != NrrdEncoding::Raw && h.byteSkip < 0)
    failLoad(path, "byte skip -1 is only allowed with raw encoding");
  if (h.subdim > h.dimension) failLoad(path, "data file subdimension exceeds the dimension");
  h.sizes = sizes;
  if (dim == 4) {
    // The axis that is not spatial comes out: what is left is the 3D grid.
    if (!kinds.empty() && kinds.size() != dim)
      failLoad(path, "kinds count does not match dimension");
    h.extra = pickNrrdExtraAxis(path, sizes, directions, kinds);
    const auto cut = static_cast<ptrdiff_t>(h.extra.axis);
    sizes.erase(sizes.begin() + cut);
    if (!spacings.empty()) spacings.erase(spacings.begin() + cut);
    if (!directions.empty()) directions.erase(directions.begin() + cut);
  }
  const size_t spatial = sizes.size();

  h.layout.dims = {1, 1, 1};
  for (size_t a = 0; a < spatial; ++a) {
    h.layout.dims[a] = sizes[a];
    if (!directions.empty() && !directions[a].empty()) {
      // hypot, not the root of the summed squares: a spacing of 1e-200 or 1e200 squared
      // would underflow to 0 or overflow to infinity (and be refused).
      const std::vector<double>& c = directions[a];
      h.layout.spacing[a] = std::hypot(c.size() > 0 ? c[0] : 0.0, c.size() > 1 ? c[1] : 0.0,
                                       c.size() > 2 ? c[2] : 0.0);  // checked in makeVolume
    } else if (!spacings.empty() && !std::isnan(spacings[a])) {
      h.layout.spacing[a] = spacings[a];  // NaN means "not a spatial axis": keep 1
    }
  }
  if (!origin.empty()) {
    for (size_t a = 0; a < origin[0].size() && a < 3; ++a) h.layout.origin[a] = origin[0][a];
  }
  for (size_t a = 0; a < spatial; ++a) {
    if (directions.empty() || directions[a].empty()) continue;
    for (size_t c = 0; c < directions[a].size() && c < 3; ++c)
      h.layout.direction[a][c] = directions[a][c] / h.layout.spacing[a];
  }
  applyNrrdSpace(space, h.layout);
  return h;
}

}  // namespace ewa
