// Parses and checks Zarr v2 .zarray files and OME-NGFF multiscales (.zattrs) with nlohmann-json.
#include "io/zarr_metadata.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/side_file.h"

namespace ewa {

namespace {

using nlohmann::json;

// A rank far above any image's (5 for OME-NGFF) that still bounds the loops over axes.
constexpr size_t kMaxRank = 32;

json parseJson(const std::string& path, const std::string& text, const char* what) {
  try {
    return json::parse(text);
  } catch (const std::exception& e) {
    failLoad(path, std::string("not valid JSON in ") + what + " (" + problemText(e) + ")");
  }
}

// A value of the file for a message: strings quoted, numbers and lists as JSON writes them.
std::string shown(const json& j) {
  if (j.is_string()) return quoteText(j.get<std::string>(), 80);
  const std::string text = j.dump();
  return text.size() > 80 ? text.substr(0, 80) + "..." : text;
}

std::vector<int64_t> positiveIntegers(const std::string& path, const json& doc, const char* key) {
  const auto it = doc.find(key);
  if (it == doc.end()) failLoad(path, std::string("has no \"") + key + "\"");
  if (!it->is_array() || it->empty() || it->size() > kMaxRank)
    failLoad(path,
             std::string("\"") + key + "\" must be a list of 1 to 32 sizes, not " + shown(*it));
  std::vector<int64_t> out;
  for (const json& v : *it) {
    // Zarr allows zero-length axes; an empty array holds no volume, so they are refused too.
    if (!v.is_number_integer() || v.get<int64_t>() <= 0)
      failLoad(path, std::string("\"") + key + "\" must hold positive integers, not " + shown(*it));
    out.push_back(v.get<int64_t>());
  }
  return out;
}

// numpy's type strings: byte order ('<', '>', '|'), kind and size ("<u2", "|u1", ">f4").
void parseDtype(const std::string& path, const json& j, ZarrArrayMeta& meta) {
  if (!j.is_string())
    failLoad(path, "dtype " + shown(j) +
                       " is not read (structured types are not; a voxel is one number)");
  const std::string d = j.get<std::string>();
  const std::string bad =
      "dtype " + quoteText(d) + " is not read (integers of 8 to 64 bits, float32, float64, bool)";
  if (d.size() < 3 || (d[0] != '<' && d[0] != '>' && d[0] != '|')) failLoad(path, bad);
  const std::string kind = d.substr(1);
  static const std::pair<const char*, FileScalar> kTypes[] = {
      {"i1", FileScalar::Int8},    {"u1", FileScalar::UInt8},  {"b1", FileScalar::UInt8},
      {"i2", FileScalar::Int16},   {"u2", FileScalar::UInt16}, {"i4", FileScalar::Int32},
      {"u4", FileScalar::UInt32},  {"i8", FileScalar::Int64},  {"u8", FileScalar::UInt64},
      {"f4", FileScalar::Float32}, {"f8", FileScalar::Float64}};
  for (const auto& [name, type] : kTypes) {
    if (kind != name) continue;
    meta.type = type;
    meta.bigEndian = d[0] == '>' && fileScalarSize(type) > 1;
    return;
  }
  failLoad(path, bad);
}

void parseCompressor(const std::string& path, const json& doc, ZarrArrayMeta& meta) {
  const auto it = doc.find("compressor");
  if (it == doc.end() || it->is_null()) return;
  const auto id = it->is_object() ? it->find("id") : it->end();
  if (!it->is_object() || id == it->end() || !id->is_string())
    failLoad(path, "compressor " + shown(*it) + " has no \"id\"");
  const std::string name = id->get<std::string>();
  static const std::pair<const char*, ZarrCodec> kCodecs[] = {{"blosc", ZarrCodec::Blosc},
                                                              {"zstd", ZarrCodec::Zstd},
                                                              {"zlib", ZarrCodec::Zlib},
                                                              {"gzip", ZarrCodec::Gzip},
                                                              {"bz2", ZarrCodec::Bz2}};
  for (const auto& [codecName, codec] : kCodecs) {
    if (name == codecName) {
      meta.codec = codec;
      return;
    }
  }
  failLoad(path,
           "compressor " + quoteText(name) + " is not read (blosc, zstd, zlib, gzip, bz2 or none)");
}

// fill_value: a number, "NaN", "Infinity", "-Infinity" (floats) or null; a whole number within
// the type's range for integers.
void parseFill(const std::string& path, const json& doc, ZarrArrayMeta& meta) {
  const auto it = doc.find("fill_value");
  if (it == doc.end() || it->is_null()) return;
  const bool real = meta.type == FileScalar::Float32 || meta.type == FileScalar::Float64;
  double v = 0.0;
  if (it->is_boolean()) {
    v = it->get<bool>() ? 1.0 : 0.0;
  } else if (it->is_number()) {
    v = it->get<double>();
  } else if (it->is_string() && real) {
    const std::string s = it->get<std::string>();
    if (s == "NaN")
      v = std::numeric_limits<double>::quiet_NaN();
    else if (s == "Infinity")
      v = std::numeric_limits<double>::infinity();
    else if (s == "-Infinity")
      v = -std::numeric_limits<double>::infinity();
    else
      failLoad(path, "fill_value " + shown(*it) + " is not a number");
  } else {
    failLoad(path, "fill_value " + shown(*it) + " is not a number");
  }
  if (!real) {
    const size_t bits = 8 * fileScalarSize(meta.type);
    const bool isSigned = meta.type == FileScalar::Int8 || meta.type == FileScalar::Int16 ||
                          meta.type == FileScalar::Int32 || meta.type == FileScalar::Int64;
    const double hi = std::ldexp(1.0, int(isSigned ? bits - 1 : bits));
    const double lo = isSigned ? -hi : 0.0;
    if (!(v == std::floor(v) && v >= lo && v < hi))
      failLoad(path, "fill_value " + shown(*it) + " does not fit the array's " +
                         fileScalarName(meta.type) + " type");
  }
  meta.fillValue = v;
}

}  // namespace

ZarrArrayMeta parseZarrArray(const std::string& path, const std::string& text) {
  const json doc = parseJson(path, text, ".zarray");
  if (!doc.is_object()) failLoad(path, "a .zarray must hold a JSON object");
  const auto format = doc.find("zarr_format");
  if (format != doc.end() && !(format->is_number_integer() && format->get<int64_t>() == 2))
    failLoad(path, "zarr_format " + shown(*format) + " is not read (Zarr version 2 only)");
  ZarrArrayMeta meta;
  meta.shape = positiveIntegers(path, doc, "shape");
  meta.chunks = positiveIntegers(path, doc, "chunks");
  if (meta.chunks.size() != meta.shape.size())
    failLoad(path, "\"chunks\" has " + std::to_string(meta.chunks.size()) +
                       " sizes for a \"shape\" of " + std::to_string(meta.shape.size()));
  const auto dtype = doc.find("dtype");
  if (dtype == doc.end()) failLoad(path, "has no \"dtype\"");
  parseDtype(path, *dtype, meta);
  const auto order = doc.find("order");
  if (order != doc.end() && *order != "C")
    failLoad(path, "order " + shown(*order) +
                       " is not read (C order only: the last axis varies fastest)");
  const auto filters = doc.find("filters");
  if (filters != doc.end() && !filters->is_null() && !(filters->is_array() && filters->empty()))
    failLoad(path, "filters " + shown(*filters) + " are not read (none only)");
  const auto separator = doc.find("dimension_separator");
  if (separator != doc.end()) {
    if (*separator == "/")
      meta.separator = '/';
    else if (*separator != ".")
      failLoad(path, "dimension_separator " + shown(*separator) + " must be \".\" or \"/\"");
  }
  parseCompressor(path, doc, meta);
  parseFill(path, doc, meta);
  // Each size is at most 2^63, so the product is checked one factor at a time.
  uint64_t bytes = fileScalarSize(meta.type);
  for (const int64_t c : meta.chunks) {
    if (uint64_t(c) > (uint64_t(1) << 62) / bytes)
      failLoad(path, "a chunk of " + shown(doc["chunks"]) + " is more than this machine's memory");
    bytes *= uint64_t(c);
  }
  checkAllocation(path, bytes, "a chunk");
  meta.chunkBytes = bytes;
  return meta;
}

namespace {

std::vector<double> numbers(const std::string& path, const json& j, const std::string& where,
                            size_t count) {
  if (!j.is_array() || j.size() != count)
    failLoad(path,
             where + " must be a list of " + std::to_string(count) + " numbers, not " + shown(j));
  std::vector<double> out;
  for (const json& v : j) {
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      failLoad(path, where + " must hold finite numbers, not " + shown(j));
    out.push_back(v.get<double>());
  }
  return out;
}

// Applies a coordinateTransformations list (a scale, then perhaps a translation) to `level`.
void applyTransforms(const std::string& path, const json& list, size_t rank,
                     const std::string& where, ZarrLevel& level) {
  if (!list.is_array()) failLoad(path, where + " must be a list, not " + shown(list));
  for (const json& t : list) {
    const auto type = t.is_object() ? t.find("type") : t.end();
    if (!t.is_object() || type == t.end())
      failLoad(path, where + " holds " + shown(t) + ", not a transformation");
    if (*type == "identity") continue;
    const bool scale = *type == "scale", translation = *type == "translation";
    if (!scale && !translation)
      failLoad(path, where + " type " + shown(*type) + " is not read (scale, translation)");
    const char* key = scale ? "scale" : "translation";
    const auto values = t.find(key);
    if (values == t.end())
      failLoad(path,
               where + " " + key + " has no \"" + key + "\" list (a binary \"path\" is not read)");
    const std::vector<double> v = numbers(path, *values, where + " " + key, rank);
    // The later transformation acts on the earlier's result: x' = s x + t.
    if (level.scale.empty()) level.scale.assign(rank, 1.0);
    if (level.translation.empty()) level.translation.assign(rank, 0.0);
    for (size_t a = 0; a < rank; ++a) {
      if (scale) {
        if (!(v[a] > 0.0)) failLoad(path, where + " scale must be positive, not " + shown(t));
        level.scale[a] *= v[a];
        level.translation[a] *= v[a];
      } else {
        level.translation[a] += v[a];
      }
    }
  }
}

// A level's folder: relative, its parts plain names, so the file cannot send us elsewhere.
std::string checkedLevelPath(const std::string& path, const json& j) {
  const std::string bad = "dataset path " + shown(j) + " must be a folder inside the image";
  if (!j.is_string()) failLoad(path, bad);
  const std::string p = j.get<std::string>();
  if (p.empty() || p.size() > 256 || p.front() == '/' || p.back() == '/') failLoad(path, bad);
  size_t start = 0;
  while (start <= p.size()) {
    const size_t end = std::min(p.find('/', start), p.size());
    const std::string part = p.substr(start, end - start);
    if (part.empty() || part == "." || part == "..") failLoad(path, bad);
    for (const unsigned char c : part)
      if (c < 0x20 || c == 0x7f || c == '\\') failLoad(path, bad);
    start = end + 1;
  }
  return p;
}

std::vector<ZarrAxis> parseAxes(const std::string& path, const json& image) {
  std::vector<ZarrAxis> axes;
  const auto list = image.find("axes");
  if (list == image.end()) return axes;
  if (!list->is_array() || list->empty() || list->size() > kMaxRank)
    failLoad(path, "multiscales axes must be a list of 1 to 32 axes, not " + shown(*list));
  for (const json& a : *list) {
    ZarrAxis axis;
    if (a.is_string()) {  // version 0.3: names only
      axis.name = a.get<std::string>();
    } else if (a.is_object() && a.contains("name") && a["name"].is_string()) {
      axis.name = a["name"].get<std::string>();
      if (a.contains("type") && a["type"].is_string()) axis.type = a["type"].get<std::string>();
      if (a.contains("unit") && a["unit"].is_string()) axis.unit = a["unit"].get<std::string>();
    } else {
      failLoad(path, "multiscales axis " + shown(a) + " has no name");
    }
    // Names alone (0.3) say the type: t time, c channel, x, y, z space.
    if (axis.type.empty()) {
      if (axis.name == "t") axis.type = "time";
      if (axis.name == "c") axis.type = "channel";
      if (axis.name == "x" || axis.name == "y" || axis.name == "z") axis.type = "space";
    }
    axes.push_back(axis);
  }
  return axes;
}

}  // namespace

std::optional<ZarrMultiscale> parseZarrMultiscales(const std::string& path,
                                                   const std::string& text) {
  const json doc = parseJson(path, text, ".zattrs");
  if (!doc.is_object()) failLoad(path, "a .zattrs must hold a JSON object");
  const auto list = doc.find("multiscales");
  if (list == doc.end()) return std::nullopt;
  if (!list->is_array() || list->empty() || !(*list)[0].is_object())
    failLoad(path, "\"multiscales\" must be a list of images, not " + shown(*list));
  const json& image = (*list)[0];
  ZarrMultiscale out;
  if (image.contains("name") && image["name"].is_string())
    out.name = image["name"].get<std::string>();
  out.axes = parseAxes(path, image);
  const auto datasets = image.find("datasets");
  if (datasets == image.end() || !datasets->is_array() || datasets->empty() ||
      datasets->size() > 64)
    failLoad(path, "multiscales \"datasets\" must list 1 to 64 levels");
  for (size_t i = 0; i < datasets->size(); ++i) {
    const json& d = (*datasets)[i];
    const std::string where = "datasets[" + std::to_string(i) + "]";
    if (!d.is_object() || !d.contains("path")) failLoad(path, where + " has no \"path\"");
    ZarrLevel level;
    level.path = checkedLevelPath(path, d["path"]);
    // Without axes (0.1, 0.2) the transformations' rank is not known; those versions had none.
    if (d.contains("coordinateTransformations") && !out.axes.empty())
      applyTransforms(path, d["coordinateTransformations"], out.axes.size(),
                      where + " coordinateTransformations", level);
    if (image.contains("coordinateTransformations") && !out.axes.empty())
      applyTransforms(path, image["coordinateTransformations"], out.axes.size(),
                      "multiscales coordinateTransformations", level);
    out.levels.push_back(level);
  }
  return out;
}

}  // namespace ewa
