// Transfer-function presets: point tables in HU or range fractions, placed on a volume's range.
#include "core/transfer_function_presets.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace ewa {
namespace {

// A point of a preset: position (HU or fraction of the range), alpha or colour.
struct PresetOpacity {
  double at, alpha;
};
struct PresetColor {
  double at, r, g, b;
};

enum class Placement { Hounsfield, Fraction };

struct Preset {
  const char* name;
  Placement placement;
  std::vector<PresetOpacity> opacity;  // empty: a colour map
  std::vector<PresetColor> color;
};

// Alphas are per opacity unit distance (the smallest spacing by default), i.e. per voxel, so
// soft tissue stays a haze through a hundred voxels while bone turns opaque within a few.
const std::vector<Preset>& presets() {
  static const std::vector<Preset> table = {
      {"CT bone",
       Placement::Hounsfield,
       {{-1000, 0.0}, {150, 0.0}, {350, 0.25}, {800, 0.7}, {3000, 0.85}},
       {{-1000, 0.3, 0.1, 0.05},
        {150, 0.55, 0.25, 0.15},
        {400, 0.9, 0.75, 0.55},
        {1000, 1.0, 0.96, 0.88},
        {3000, 1.0, 1.0, 1.0}}},
      {"CT soft tissue",
       Placement::Hounsfield,
       {{-1000, 0.0}, {-200, 0.0}, {-50, 0.02}, {80, 0.06}, {200, 0.04}, {400, 0.4}, {3000, 0.8}},
       {{-1000, 0.2, 0.05, 0.05},
        {-200, 0.6, 0.3, 0.2},
        {40, 0.85, 0.45, 0.35},
        {200, 0.95, 0.75, 0.6},
        {500, 1.0, 0.97, 0.9},
        {3000, 1.0, 1.0, 1.0}}},
      {"MR",
       Placement::Fraction,
       {{0.0, 0.0}, {0.1, 0.0}, {0.3, 0.02}, {0.6, 0.12}, {1.0, 0.35}},
       {{0.0, 0.0, 0.0, 0.0},
        {0.1, 0.3, 0.22, 0.25},
        {0.45, 0.85, 0.68, 0.62},
        {0.75, 0.98, 0.9, 0.82},
        {1.0, 1.0, 1.0, 1.0}}},
      {"Grayscale ramp",
       Placement::Fraction,
       {{0.0, 0.0}, {1.0, 0.4}},
       {{0.0, 0.0, 0.0, 0.0}, {1.0, 1.0, 1.0, 1.0}}},
      // matplotlib's viridis and inferno sampled at ninths of the range.
      {"Viridis (colour map)",
       Placement::Fraction,
       {},
       {{0.0, 0.267004, 0.004874, 0.329415},
        {0.125, 0.282623, 0.140926, 0.457517},
        {0.25, 0.229739, 0.322361, 0.545706},
        {0.375, 0.172719, 0.448791, 0.557885},
        {0.5, 0.127568, 0.566949, 0.550556},
        {0.625, 0.157851, 0.683765, 0.501686},
        {0.75, 0.369214, 0.788888, 0.382914},
        {0.875, 0.678489, 0.863742, 0.189503},
        {1.0, 0.993248, 0.906157, 0.143936}}},
      {"Inferno (colour map)",
       Placement::Fraction,
       {},
       {{0.0, 0.001462, 0.000466, 0.013866},
        {0.125, 0.087411, 0.044556, 0.224813},
        {0.25, 0.258234, 0.038571, 0.406485},
        {0.375, 0.416331, 0.090203, 0.432943},
        {0.5, 0.578304, 0.148039, 0.404411},
        {0.625, 0.735683, 0.215906, 0.330245},
        {0.75, 0.865006, 0.316822, 0.226055},
        {0.875, 0.954506, 0.468744, 0.099874},
        {1.0, 0.988362, 0.998364, 0.644924}}},
      // ParaView's default diverging map (Moreland's cool to warm).
      {"Cool to warm (colour map)",
       Placement::Fraction,
       {},
       {{0.0, 0.231373, 0.298039, 0.752941},
        {0.5, 0.865003, 0.865003, 0.865003},
        {1.0, 0.705882, 0.0156863, 0.14902}}},
      {"Rainbow (colour map)",
       Placement::Fraction,
       {},
       {{0.0, 0.0, 0.0, 1.0},
        {0.25, 0.0, 1.0, 1.0},
        {0.5, 0.0, 1.0, 0.0},
        {0.75, 1.0, 1.0, 0.0},
        {1.0, 1.0, 0.0, 0.0}}},
  };
  return table;
}

// Maps a preset position onto the volume's values.
double place(const Preset& p, double at, double lo, double hi) {
  if (p.placement == Placement::Fraction) return lo + at * (hi - lo);
  if (lo <= -500.0 && hi >= 500.0) return std::clamp(at, lo, hi);  // already HU
  // Points above 2000 HU (dense bone, metal) land on hi.
  return std::clamp(lo + (at + 1000.0) / 3000.0 * (hi - lo), lo, hi);
}

// "Cool to warm (colour map)" -> "cool-to-warm": lower case, words joined by '-'.
std::string keyOf(const std::string& name) {
  std::string key = name.substr(0, name.find(" ("));
  for (char& c : key) c = c == ' ' ? '-' : char(std::tolower(static_cast<unsigned char>(c)));
  return key;
}

}  // namespace

const std::vector<TransferFunctionPresetInfo>& transferFunctionPresets() {
  static const std::vector<TransferFunctionPresetInfo> infos = [] {
    std::vector<TransferFunctionPresetInfo> out;
    for (const Preset& p : presets()) out.push_back({p.name, p.opacity.empty(), keyOf(p.name)});
    return out;
  }();
  return infos;
}

TransferFunction applyTransferFunctionPreset(const TransferFunction& current,
                                             const std::string& name, double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo)
    throw std::invalid_argument("preset: value range must be finite with lo <= hi");
  const auto& table = presets();
  const auto it = std::find_if(table.begin(), table.end(), [&](const Preset& p) {
    return name == p.name || name == keyOf(p.name);
  });
  if (it == table.end())
    throw std::invalid_argument("unknown transfer-function preset \"" + name + "\"");
  TransferFunction tf = current;
  tf.color.clear();
  for (const PresetColor& c : it->color)
    tf.color.push_back({place(*it, c.at, lo, hi), {c.r, c.g, c.b}});
  if (!it->opacity.empty()) {
    tf.opacity.clear();
    for (const PresetOpacity& o : it->opacity)
      tf.opacity.push_back({place(*it, o.at, lo, hi), o.alpha});
  }
  tf.sortPoints();  // HU points clamped to the range may coincide; the order is kept
  return tf;
}

}  // namespace ewa
