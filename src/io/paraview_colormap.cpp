// ParaView colour-map presets: strict parsing with one-line errors, and placing a map on a range.
#include "io/paraview_colormap.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "io/side_file.h"
#include "io/transfer_function_io.h"

namespace ewa {
namespace {

using nlohmann::json;

struct FormatError {
  std::string problem;
};

// Flat array of numbers whose length is a multiple of `tuple`.
std::vector<double> flatNumbers(const json& j, const std::string& where, size_t tuple) {
  if (!j.is_array()) throw FormatError{where + " must be an array of numbers"};
  if (j.empty() || j.size() % tuple != 0)
    throw FormatError{where + " must hold groups of " + std::to_string(tuple) + " numbers, got " +
                      std::to_string(j.size())};
  std::vector<double> out;
  for (size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_number() || !std::isfinite(j[i].get<double>()))
      throw FormatError{where + "[" + std::to_string(i) + "] is not a finite number"};
    out.push_back(j[i].get<double>());
  }
  return out;
}

double unit(double v, const std::string& where) {
  if (v < 0.0 || v > 1.0) {
    std::ostringstream out;
    out << where << " is " << v << ", outside [0, 1]";
    throw FormatError{out.str()};
  }
  return v;
}

ImportedColorMap presetFrom(const json& p, size_t index) {
  ImportedColorMap map;
  map.name = "preset " + std::to_string(index);
  if (p.contains("Name") && p["Name"].is_string()) map.name = p["Name"].get<std::string>();
  const std::string where = "\"" + map.name + "\"";
  const std::vector<double> rgb = flatNumbers(p["RGBPoints"], where + " RGBPoints", 4);
  for (size_t i = 0; i < rgb.size(); i += 4) {
    const std::string at = where + " RGBPoints[" + std::to_string(i / 4) + "]";
    map.color.push_back({rgb[i],
                         {unit(rgb[i + 1], at + " red"), unit(rgb[i + 2], at + " green"),
                          unit(rgb[i + 3], at + " blue")}});
  }
  if (p.contains("Points")) {
    const std::vector<double> pts = flatNumbers(p["Points"], where + " Points", 4);
    for (size_t i = 0; i < pts.size(); i += 4)
      map.opacity.push_back(
          {pts[i], unit(pts[i + 1], where + " Points[" + std::to_string(i / 4) + "] opacity")});
  }
  std::stable_sort(map.color.begin(), map.color.end(),
                   [](const ColorPoint& a, const ColorPoint& b) { return a.value < b.value; });
  std::stable_sort(map.opacity.begin(), map.opacity.end(),
                   [](const OpacityPoint& a, const OpacityPoint& b) { return a.value < b.value; });
  return map;
}

std::vector<ImportedColorMap> fromJson(const json& doc) {
  std::vector<ImportedColorMap> maps;
  if (doc.is_object()) {
    if (!doc.contains("RGBPoints"))
      throw FormatError{"no \"RGBPoints\" (not a ParaView colour-map preset)"};
    maps.push_back(presetFrom(doc, 0));
    return maps;
  }
  if (!doc.is_array()) throw FormatError{"expected a ParaView preset object or an array of them"};
  for (size_t i = 0; i < doc.size(); ++i) {
    if (!doc[i].is_object()) throw FormatError{"entry " + std::to_string(i) + " is not an object"};
    if (doc[i].contains("RGBPoints")) maps.push_back(presetFrom(doc[i], i));
  }
  if (maps.empty()) throw FormatError{"no preset with \"RGBPoints\" in the file"};
  return maps;
}

}  // namespace

std::vector<ImportedColorMap> parseParaViewPresets(const std::string& text,
                                                   const std::string& nameForErrors) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    std::string what = e.what();
    const size_t close = what.find("] ");
    if (close != std::string::npos) what = what.substr(close + 2);
    std::replace(what.begin(), what.end(), '\n', ' ');
    throw std::runtime_error(nameForErrors + ": invalid JSON: " + what);
  }
  try {
    return fromJson(doc);
  } catch (const FormatError& e) {
    throw std::runtime_error(nameForErrors + ": " + e.problem);
  }
}

std::vector<ImportedColorMap> loadParaViewPresets(const std::string& path) {
  return parseParaViewPresets(readSideFile(path, "preset file"), path);
}

TransferFunction applyImportedColorMap(const TransferFunction& current, const ImportedColorMap& map,
                                       double lo, double hi, bool rescale) {
  TransferFunction tf = current;
  // The colour points' span is the map's range (ParaView rescales both functions by it).
  const double from = map.color.front().value, to = map.color.back().value;
  auto placeValue = [&](double v) {
    if (!rescale) return v;
    if (!(to > from)) return lo;
    return lo + (v - from) / (to - from) * (hi - lo);
  };
  tf.color.clear();
  for (const ColorPoint& c : map.color) tf.color.push_back({placeValue(c.value), c.rgb});
  if (!map.opacity.empty()) {
    tf.opacity.clear();
    for (const OpacityPoint& o : map.opacity) tf.opacity.push_back({placeValue(o.value), o.alpha});
  }
  tf.sortPoints();
  return tf;
}

TransferFunction loadTransferFunctionOrPreset(const std::string& path,
                                              const TransferFunction& current, double lo, double hi,
                                              std::string* what) {
  try {
    TransferFunction tf = loadTransferFunction(path);
    *what = "loaded " + path;
    return tf;
  } catch (const std::runtime_error& own) {
    std::vector<ImportedColorMap> maps;
    try {
      maps = loadParaViewPresets(path);
    } catch (const std::runtime_error&) {
      throw own;  // neither: say what is wrong for ewaview's own format
    }
    *what = "imported \"" + maps.front().name + "\" from " + path;
    return applyImportedColorMap(current, maps.front(), lo, hi, true);
  }
}

}  // namespace ewa
