// Transfer-function JSON: strict parsing with one-line errors, exact-round-trip writing.
#include "io/transfer_function_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/side_file.h"

namespace ewa {
namespace {

using nlohmann::json;

// Problems found while reading the document; turned into "<name>: <problem>" at the top.
struct FormatError {
  std::string problem;
};

std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

// nlohmann's messages start with "[json.exception.parse_error.101] "; the rest says where.
std::string withoutExceptionTag(const std::string& what) {
  const size_t close = what.find("] ");
  return what.rfind("[json.exception.", 0) == 0 && close != std::string::npos
             ? what.substr(close + 2)
             : what;
}

double number(const json& j, const std::string& where) {
  if (!j.is_number()) throw FormatError{where + " must be a number, got " + oneLine(j.dump())};
  return j.get<double>();
}

// Reads an array of points, each an array of exactly `width` numbers.
std::vector<std::vector<double>> points(const json& j, const std::string& key, size_t width,
                                        const char* shape) {
  if (!j.is_array()) throw FormatError{"\"" + key + "\" must be an array of " + shape + " points"};
  std::vector<std::vector<double>> out;
  for (size_t i = 0; i < j.size(); ++i) {
    const std::string where = key + "[" + std::to_string(i) + "]";
    const json& p = j[i];
    if (!p.is_array() || p.size() != width)
      throw FormatError{where + " must be " + shape + ", got " + oneLine(p.dump())};
    std::vector<double> values;
    for (size_t c = 0; c < width; ++c)
      values.push_back(number(p[c], where + "[" + std::to_string(c) + "]"));
    out.push_back(values);
  }
  return out;
}

TransferFunction fromJson(const json& doc) {
  if (!doc.is_object()) throw FormatError{"the top level must be a JSON object"};
  for (const auto& item : doc.items()) {
    const std::string& key = item.key();
    if (key == "opacity" || key == "color" || key == "opacity_unit_distance") continue;
    if ((key == "name" || key == "description") && item.value().is_string()) continue;
    throw FormatError{"unknown key \"" + key +
                      "\" (expected opacity, color, opacity_unit_distance, name, description)"};
  }
  if (!doc.contains("opacity")) throw FormatError{"missing \"opacity\""};
  TransferFunction tf;
  for (const auto& p : points(doc["opacity"], "opacity", 2, "[value, alpha]"))
    tf.opacity.push_back({p[0], p[1]});
  if (doc.contains("color")) {
    for (const auto& p : points(doc["color"], "color", 4, "[value, r, g, b]"))
      tf.color.push_back({p[0], {p[1], p[2], p[3]}});
  }
  if (doc.contains("opacity_unit_distance"))
    tf.opacityUnitDistance = number(doc["opacity_unit_distance"], "opacity_unit_distance");
  tf.sortPoints();
  try {
    tf.validate();
  } catch (const std::invalid_argument& e) {
    throw FormatError{e.what()};
  }
  return tf;
}

// Shortest text that reads back as the same double (nlohmann prints round-trip digits).
std::string text(double v) {
  return json(v).dump();
}

}  // namespace

TransferFunction parseTransferFunctionJson(const std::string& text,
                                           const std::string& nameForErrors) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throw std::runtime_error(nameForErrors +
                             ": invalid JSON: " + oneLine(withoutExceptionTag(e.what())));
  }
  try {
    return fromJson(doc);
  } catch (const FormatError& e) {
    throw std::runtime_error(nameForErrors + ": " + oneLine(e.problem));  // keys may hold \n
  } catch (const json::exception& e) {
    throw std::runtime_error(nameForErrors + ": " + oneLine(withoutExceptionTag(e.what())));
  }
}

TransferFunction loadTransferFunction(const std::string& path) {
  return parseTransferFunctionJson(readSideFile(path, "transfer-function file"), path);
}

std::string transferFunctionToJson(const TransferFunction& tf) {
  std::ostringstream out;
  out << "{\n  \"opacity\": [";
  for (size_t i = 0; i < tf.opacity.size(); ++i) {
    const OpacityPoint& p = tf.opacity[i];
    out << (i ? ",\n    " : "\n    ") << "[" << text(p.value) << ", " << text(p.alpha) << "]";
  }
  out << (tf.opacity.empty() ? "],\n" : "\n  ],\n") << "  \"color\": [";
  for (size_t i = 0; i < tf.color.size(); ++i) {
    const ColorPoint& p = tf.color[i];
    out << (i ? ",\n    " : "\n    ") << "[" << text(p.value) << ", " << text(p.rgb.r) << ", "
        << text(p.rgb.g) << ", " << text(p.rgb.b) << "]";
  }
  out << (tf.color.empty() ? "],\n" : "\n  ],\n");
  out << "  \"opacity_unit_distance\": " << text(tf.opacityUnitDistance) << "\n}\n";
  return out.str();
}

void saveTransferFunction(const std::string& path, const TransferFunction& unsorted) {
  TransferFunction tf = unsorted;
  tf.sortPoints();
  try {
    tf.validate();
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": not saved: " + e.what());
  }
  writeFileAtomically(path, transferFunctionToJson(tf));
}

std::string sidecarTransferFunctionPath(const std::string& volumePath, int channel) {
  std::filesystem::path p(volumePath);
  const std::string own = channel > 0 ? ".c" + std::to_string(channel) : std::string();
  return (p.parent_path() / (p.stem().string() + own + ".tf.json")).string();
}

}  // namespace ewa
