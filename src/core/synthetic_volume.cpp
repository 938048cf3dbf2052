// Synthetic volumes: spec parsing, the generators and the transfer functions that show them.
#include "core/synthetic_volume.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <stdexcept>

namespace ewa {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::invalid_argument specError(const std::string& spec, const std::string& problem) {
  return std::invalid_argument("--synthetic " + spec + ": " + problem);
}

// The optional ":number" of a spec as a whole number in [lo, hi], or `fallback` without one.
int parseParameter(const std::string& spec, const std::string& text, bool present, int fallback,
                   int lo, int hi, const char* what) {
  if (!present) return fallback;
  if (text.empty() || text.size() > 9 ||
      !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
    throw specError(spec, std::string(what) + " '" + text + "' is not a whole number");
  const int n = std::stoi(text);
  if (n < lo || n > hi)
    throw specError(spec, std::string(what) + " " + text + " is outside [" + std::to_string(lo) +
                              ", " + std::to_string(hi) + "]");
  return n;
}

Volume makeVolume(std::array<int64_t, 3> dims, glm::dvec3 spacing, const std::vector<float>& v,
                  glm::dvec3 origin = glm::dvec3(0.0)) {
  std::vector<uint8_t> bytes(v.size() * sizeof(float));
  std::memcpy(bytes.data(), v.data(), bytes.size());
  return Volume(dims, spacing, origin, ScalarType::Float32, std::move(bytes));
}

Volume makeVolume(std::array<int64_t, 3> dims, glm::dvec3 spacing, std::vector<uint8_t> v) {
  return Volume(dims, spacing, glm::dvec3(0.0), ScalarType::UInt8, std::move(v));
}

// Voxels lo <= (i, j, k) < hi of the n^3 Marschner-Lobb volume, where the whole one has them.
SyntheticVolume marschnerLobbBox(int n, const std::array<int64_t, 3>& lo,
                                 const std::array<int64_t, 3>& hi) {
  const std::array<int64_t, 3> dims{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  std::vector<float> values(size_t(dims[0] * dims[1] * dims[2]));
  auto coord = [n](int64_t i) { return -1.0 + 2.0 * double(i) / (n - 1); };
  size_t at = 0;
  for (int64_t k = lo[2]; k < hi[2]; ++k)
    for (int64_t j = lo[1]; j < hi[1]; ++j)
      for (int64_t i = lo[0]; i < hi[0]; ++i)
        values[at++] = float(marschnerLobb(coord(i), coord(j), coord(k)));
  TransferFunction tf;
  // A steep step at 0.5 makes the region above the iso-value solid, so what one sees is the
  // 0.5 iso-surface, the usual way to judge reconstruction filters on this signal.
  tf.opacity = {{0.45, 0.0}, {0.55, 0.9}, {1.0, 0.9}};
  tf.color = {{0.45, {0.85, 0.42, 0.22}}, {0.75, {0.95, 0.75, 0.45}}, {1.0, {1.0, 0.95, 0.85}}};
  // World units are voxels from the whole volume's first: the box's first voxel sits at lo.
  const glm::dvec3 origin{double(lo[0]), double(lo[1]), double(lo[2])};
  return {makeVolume(dims, glm::dvec3(1.0), values, origin), tf,
          "marschner-lobb:" + std::to_string(n)};
}

SyntheticVolume marschnerLobbVolume(int n) {
  return marschnerLobbBox(n, {0, 0, 0}, {n, n, n});
}

SyntheticVolume sphereVolume(int n) {
  std::vector<uint8_t> values(size_t(n) * n * n);
  const double center = 0.5 * (n - 1), radius = 0.4 * n, edge = 0.75;  // edge: half-width
  size_t at = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double r = std::sqrt((i - center) * (i - center) + (j - center) * (j - center) +
                                   (k - center) * (k - center));
        // Smoothstep from inside to outside over [radius - edge, radius + edge].
        const double t = std::clamp((r - (radius - edge)) / (2.0 * edge), 0.0, 1.0);
        values[at++] = uint8_t(std::lround(255.0 * (1.0 - t * t * (3.0 - 2.0 * t))));
      }
  TransferFunction tf;
  // Alpha is the opacity across the whole diameter, so the ball looks the same at any N.
  tf.opacityUnitDistance = 2.0 * radius;
  tf.opacity = {{0.0, 0.0}, {255.0, 0.7}};
  tf.color = {{0.0, {0.95, 0.35, 0.1}}, {255.0, {1.0, 0.6, 0.2}}};
  return {makeVolume({n, n, n}, glm::dvec3(1.0), std::move(values)), tf,
          "sphere:" + std::to_string(n)};
}

SyntheticVolume boxVolume(int n) {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {255.0, 0.05}};
  tf.color = {{0.0, {0.6, 0.8, 1.0}}, {255.0, {0.6, 0.8, 1.0}}};
  return {makeVolume({n, n, n}, glm::dvec3(1.0), std::vector<uint8_t>(size_t(n) * n * n, 255)), tf,
          "box:" + std::to_string(n)};
}

SyntheticVolume checkerboardVolume(int square) {
  const int size = 400;
  std::vector<uint8_t> values(size_t(size) * size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      values[size_t(j) * size + i] = ((i / square + j / square) % 2) + 1;
  TransferFunction tf;
  // One voxel thick: a layer of alpha 0.98 per voxel makes the sheet nearly opaque head-on and
  // more so at grazing angles. Value 0 is unused; the ramp below 1 only matters for filtering.
  tf.opacity = {{0.0, 0.0}, {1.0, 0.98}, {2.0, 0.98}};
  tf.color = {{1.0, {1.0, 0.0, 0.0}}, {2.0, {1.0, 1.0, 1.0}}};
  return {makeVolume({size, size, 1}, glm::dvec3(1.0), std::move(values)), tf,
          "checkerboard:" + std::to_string(square)};
}

SyntheticVolume zebraVolume(int ratio) {
  const int nx = 256 * ratio, ny = 256;
  // Local stripe frequency along x rises from 4 to 32·ratio cycles per sheet width, so the
  // finest stripes still span 8 samples of the dense axis; a gentle wave along y (at most
  // ~19 cycles across the 256 coarse samples) bends them like a zebra's.
  const double f0 = 4.0, f1 = 32.0 * ratio, wave = 1.5, sharpness = 2.5;
  std::vector<float> values(size_t(nx) * ny);
  for (int j = 0; j < ny; ++j) {
    const double v = double(j) / (ny - 1);
    for (int i = 0; i < nx; ++i) {
      const double u = double(i) / (nx - 1);
      const double phase = f0 * u + 0.5 * (f1 - f0) * u * u + wave * std::sin(2.0 * kPi * 2.0 * v);
      const double s = std::tanh(sharpness * std::sin(2.0 * kPi * phase)) / std::tanh(sharpness);
      values[size_t(j) * nx + i] = float(0.5 + 0.5 * s);
    }
  }
  TransferFunction tf;
  tf.opacity = {{0.0, 0.98}, {1.0, 0.98}};
  tf.color = {{0.0, {0.0, 0.0, 0.0}}, {1.0, {1.0, 1.0, 1.0}}};
  return {makeVolume({nx, ny, 1}, glm::dvec3(1.0 / ratio, 1.0, 1.0), values), tf,
          "zebra:" + std::to_string(ratio)};
}

}  // namespace

double marschnerLobb(double x, double y, double z) {
  const double fM = 6.0, alpha = 0.25;
  const double r = std::sqrt(x * x + y * y);
  const double rho = std::cos(2.0 * kPi * fM * std::cos(kPi * r / 2.0));
  return (1.0 - std::sin(kPi * z / 2.0) + alpha * (1.0 + rho)) / (2.0 * (1.0 + alpha));
}

namespace {

// Each synthetic volume: its name, its number's letter, meaning, default and range.
struct SyntheticKind {
  const char* name;
  const char* letter;  // in the spec's form, "sphere[:N]"
  const char* what;    // in error messages
  int fallback, lo, hi;
  SyntheticVolume (*make)(int);
};

constexpr SyntheticKind kSyntheticKinds[] = {
    {"marschner-lobb", "N", "size", 41, 2, 512, marschnerLobbVolume},
    {"sphere", "N", "size", 64, 2, 512, sphereVolume},
    {"box", "N", "size", 32, 2, 512, boxVolume},
    {"checkerboard", "S", "square size", 10, 1, 200, checkerboardVolume},
    {"zebra", "RATIO", "ratio", 4, 1, 16, zebraVolume},
};

}  // namespace

SyntheticVolume makeSyntheticVolume(const std::string& spec) {
  const size_t colon = spec.find(':');
  const std::string name = spec.substr(0, colon);
  const bool hasNumber = colon != std::string::npos;
  const std::string number = hasNumber ? spec.substr(colon + 1) : std::string();
  std::string names;  // "a, b or c"
  const size_t count = std::size(kSyntheticKinds);
  for (size_t k = 0; k < count; ++k) {
    const SyntheticKind& kind = kSyntheticKinds[k];
    if (name == kind.name)
      return kind.make(
          parseParameter(spec, number, hasNumber, kind.fallback, kind.lo, kind.hi, kind.what));
    names += (k == 0 ? "" : k + 1 == count ? " or " : ", ") + std::string(kind.name);
  }
  throw specError(spec, "unknown volume '" + name + "' (expected " + names + ")");
}

std::optional<SyntheticRegionSource> syntheticRegionSource(const std::string& spec) {
  const size_t colon = spec.find(':');
  if (spec.substr(0, colon) != "marschner-lobb") return std::nullopt;
  const bool hasNumber = colon != std::string::npos;
  const int n = parseParameter(spec, hasNumber ? spec.substr(colon + 1) : std::string(), hasNumber,
                               41, 2, 512, "size");
  SyntheticRegionSource source;
  source.dims = {n, n, n};
  source.make = [n](const std::array<int64_t, 3>& lo, const std::array<int64_t, 3>& hi) {
    return marschnerLobbBox(n, lo, hi);
  };
  return source;
}

std::vector<std::string> syntheticVolumeForms() {
  std::vector<std::string> forms;
  for (const SyntheticKind& kind : kSyntheticKinds)
    forms.push_back(std::string(kind.name) + "[:" + kind.letter + "]");
  return forms;
}

}  // namespace ewa
