// TransferFunction: interpolation, validation, baking, equality, and the histogram default.
#include "core/transfer_function.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ewa {
namespace {

// Opaque points stay finite: -ln(1e-6) is about 13.8 per unit distance.
constexpr double kMaxAlpha = 1.0 - 1e-6;

// Piecewise-linear lookup in a sorted point list; `get` reads a point's payload.
template <typename Point, typename Get>
auto interpolate(const std::vector<Point>& points, double value, Get get) {
  auto upper = std::upper_bound(points.begin(), points.end(), value,
                                [](double v, const Point& p) { return v < p.value; });
  if (upper == points.begin()) return get(points.front());
  if (upper == points.end()) return get(points.back());
  const Point& a = *(upper - 1);
  const Point& b = *upper;
  // b.value > value >= a.value, so the width is positive.
  const double t = (value - a.value) / (b.value - a.value);
  return get(a) + (get(b) - get(a)) * t;
}

// Builds "<list> point <index>: <parts...>" for validation messages.
template <typename... Parts>
std::string pointMessage(const char* list, size_t index, const Parts&... parts) {
  std::ostringstream out;
  out << list << " point " << index << ": ";
  (out << ... << parts);
  return out.str();
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

}  // namespace

void TransferFunction::sortPoints() {
  std::stable_sort(opacity.begin(), opacity.end(),
                   [](const OpacityPoint& a, const OpacityPoint& b) { return a.value < b.value; });
  std::stable_sort(color.begin(), color.end(),
                   [](const ColorPoint& a, const ColorPoint& b) { return a.value < b.value; });
}

void TransferFunction::validate() const {
  if (!(std::isfinite(opacityUnitDistance) && opacityUnitDistance > 0.0)) {
    std::ostringstream out;
    out << "opacity unit distance must be a positive finite number, got " << opacityUnitDistance;
    throw std::invalid_argument(out.str());
  }
  for (size_t i = 0; i < opacity.size(); ++i) {
    const OpacityPoint& p = opacity[i];
    require(std::isfinite(p.value),
            pointMessage("opacity", i, "value ", p.value, " is not finite"));
    require(std::isfinite(p.alpha),
            pointMessage("opacity", i, "alpha ", p.alpha, " is not finite"));
    require(p.alpha >= 0.0 && p.alpha <= 1.0,
            pointMessage("opacity", i, "alpha ", p.alpha, " is outside [0, 1]"));
    require(i == 0 || opacity[i - 1].value <= p.value,
            pointMessage("opacity", i, "points are not sorted by value (call sortPoints)"));
  }
  for (size_t i = 0; i < color.size(); ++i) {
    const ColorPoint& p = color[i];
    require(std::isfinite(p.value), pointMessage("color", i, "value ", p.value, " is not finite"));
    for (int c = 0; c < 3; ++c) {
      require(std::isfinite(p.rgb[c]) && p.rgb[c] >= 0.0 && p.rgb[c] <= 1.0,
              pointMessage("color", i, "component ", p.rgb[c], " is outside [0, 1]"));
    }
    require(i == 0 || color[i - 1].value <= p.value,
            pointMessage("color", i, "points are not sorted by value (call sortPoints)"));
  }
}

double TransferFunction::alphaAt(double value) const {
  if (opacity.empty() || std::isnan(value)) return 0.0;
  return interpolate(opacity, value, [](const OpacityPoint& p) { return p.alpha; });
}

glm::dvec3 TransferFunction::colorAt(double value) const {
  if (color.empty()) return glm::dvec3(1.0);
  if (std::isnan(value)) return color.front().rgb;
  return interpolate(color, value, [](const ColorPoint& p) { return p.rgb; });
}

double TransferFunction::extinctionAt(double value) const {
  const double alpha = std::clamp(alphaAt(value), 0.0, kMaxAlpha);
  return -std::log1p(-alpha) / opacityUnitDistance;
}

std::vector<glm::vec4> TransferFunction::bake(double lo, double hi, int n) const {
  if (n < 1) throw std::invalid_argument("bake: sample count must be at least 1");
  if (!std::isfinite(lo) || !std::isfinite(hi))
    throw std::invalid_argument("bake: range must be finite");
  std::vector<glm::vec4> table(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double v = n == 1 ? lo : lo + (hi - lo) * i / (n - 1);
    const glm::dvec3 rgb = colorAt(v);
    // A tiny unit distance makes tau overflow float; infinite tau would turn the shader's
    // colour average (sum c*tau / sum tau) into NaN, so cap it far above any visible opacity.
    const double tau = std::min(extinctionAt(v), kMaxBakedExtinction);
    table[i] = glm::vec4(float(rgb.r), float(rgb.g), float(rgb.b), float(tau));
  }
  return table;
}

bool TransferFunction::allTransparent(double lo, double hi) const {
  if (lo > hi) std::swap(lo, hi);
  if (alphaAt(lo) > 0.0 || alphaAt(hi) > 0.0) return false;
  // Between points the function is linear, so its maximum on [lo, hi] is at an end or a point.
  for (const OpacityPoint& p : opacity) {
    if (p.value >= lo && p.value <= hi && p.alpha > 0.0) return false;
  }
  return true;
}

namespace {

double finiteOr(double value, double fallback) {
  return std::isfinite(value) ? value : fallback;
}

glm::dvec3 clampColor(const glm::dvec3& rgb) {
  glm::dvec3 out;
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(rgb[c])) throw std::invalid_argument("colour component is not finite");
    out[c] = std::clamp(rgb[c], 0.0, 1.0);
  }
  return out;
}

template <typename Point>
void checkIndex(const std::vector<Point>& points, size_t index, const char* list) {
  if (index >= points.size())
    throw std::out_of_range(std::string(list) + " point " + std::to_string(index) +
                            " does not exist (" + std::to_string(points.size()) + " points)");
}

// Index after the last point whose value is <= value: where a new point goes.
template <typename Point>
size_t insertionIndex(const std::vector<Point>& points, double value) {
  return size_t(std::upper_bound(points.begin(), points.end(), value,
                                 [](double v, const Point& p) { return v < p.value; }) -
                points.begin());
}

// The value a point may take: between its neighbours, so the order never changes.
template <typename Point>
double clampBetweenNeighbours(const std::vector<Point>& points, size_t index, double value) {
  if (!std::isfinite(value)) return points[index].value;
  if (index > 0) value = std::max(value, points[index - 1].value);
  if (index + 1 < points.size()) value = std::min(value, points[index + 1].value);
  return value;
}

}  // namespace

size_t TransferFunction::addOpacityPoint(double value, double alpha) {
  if (!std::isfinite(value) || !std::isfinite(alpha))
    throw std::invalid_argument("opacity point must be finite");
  const size_t at = insertionIndex(opacity, value);
  opacity.insert(opacity.begin() + std::ptrdiff_t(at), {value, std::clamp(alpha, 0.0, 1.0)});
  return at;
}

size_t TransferFunction::addColorPoint(double value, const glm::dvec3& rgb) {
  if (!std::isfinite(value)) throw std::invalid_argument("colour point value is not finite");
  const glm::dvec3 c = clampColor(rgb);
  const size_t at = insertionIndex(color, value);
  color.insert(color.begin() + std::ptrdiff_t(at), {value, c});
  return at;
}

void TransferFunction::moveOpacityPoint(size_t index, double value, double alpha) {
  checkIndex(opacity, index, "opacity");
  OpacityPoint& p = opacity[index];
  p.value = clampBetweenNeighbours(opacity, index, value);
  p.alpha = std::clamp(finiteOr(alpha, p.alpha), 0.0, 1.0);
}

void TransferFunction::moveColorPoint(size_t index, double value) {
  checkIndex(color, index, "color");
  color[index].value = clampBetweenNeighbours(color, index, value);
}

void TransferFunction::setPointColor(size_t index, const glm::dvec3& rgb) {
  checkIndex(color, index, "color");
  color[index].rgb = clampColor(rgb);
}

void TransferFunction::removeOpacityPoint(size_t index) {
  checkIndex(opacity, index, "opacity");
  opacity.erase(opacity.begin() + std::ptrdiff_t(index));
}

void TransferFunction::removeColorPoint(size_t index) {
  checkIndex(color, index, "color");
  color.erase(color.begin() + std::ptrdiff_t(index));
}

bool operator==(const OpacityPoint& a, const OpacityPoint& b) {
  return a.value == b.value && a.alpha == b.alpha;
}

bool operator==(const ColorPoint& a, const ColorPoint& b) {
  return a.value == b.value && a.rgb == b.rgb;
}

bool operator==(const TransferFunction& a, const TransferFunction& b) {
  return a.opacity == b.opacity && a.color == b.color &&
         a.opacityUnitDistance == b.opacityUnitDistance;
}

// ---- Default transfer function from a histogram ------------------------------------------
namespace {

// Histogram smoothed by a small triangle filter, so single noisy bins do not make valleys.
std::vector<double> smoothHistogram(const std::vector<uint64_t>& h) {
  const int n = static_cast<int>(h.size());
  std::vector<double> s(h.size(), 0.0);
  const double weights[5] = {1, 2, 3, 2, 1};
  for (int b = 0; b < n; ++b) {
    double sum = 0.0, weight = 0.0;
    for (int k = -2; k <= 2; ++k) {
      if (b + k < 0 || b + k >= n) continue;
      sum += weights[k + 2] * double(h[b + k]);
      weight += weights[k + 2];
    }
    s[b] = sum / weight;
  }
  return s;
}

// Last bin of the background peak that starts at `mode`: where its tail falls below 1% of
// the peak, or earlier at the valley before the next material's peak.
int backgroundEnd(const std::vector<double>& s, int mode) {
  const int n = static_cast<int>(s.size());
  int valley = mode;
  for (int b = mode + 1; b < n; ++b) {
    if (s[b] < 0.01 * s[mode]) return b;
    if (s[b] < s[valley]) valley = b;
    // Rising well above the lowest point after the peak has fallen away: a new material.
    if (s[valley] < 0.5 * s[mode] && s[b] > 1.5 * s[valley] + 1.0) return valley;
  }
  return valley;
}

// The share of the counts in bins below `bin`.
double shareBelow(const std::vector<uint64_t>& h, int bin) {
  double below = 0.0, total = 0.0;
  for (size_t b = 0; b < h.size(); ++b) {
    total += double(h[b]);
    if (int(b) < bin) below += double(h[b]);
  }
  return total > 0.0 ? below / total : 0.0;
}

// Value below which `fraction` of the counts in bins [first, end) lie.
double quantile(const std::vector<uint64_t>& h, int first, double fraction, double lo,
                double width) {
  double total = 0.0;
  for (size_t b = first; b < h.size(); ++b) total += double(h[b]);
  double cumulative = 0.0;
  for (size_t b = first; b < h.size(); ++b) {
    const double next = cumulative + double(h[b]);
    if (next >= fraction * total && h[b] > 0) {
      const double inBin = (fraction * total - cumulative) / double(h[b]);
      return lo + (double(b) + std::clamp(inBin, 0.0, 1.0)) * width;
    }
    cumulative = next;
  }
  return lo + double(h.size()) * width;
}

// The volume's distinct values, when it has at most kMaxLabels set apart from each other (a
// binary mask, a label volume); empty otherwise. Values in neighbouring histogram bins are a
// material's noise (18 to 22 about 20), not labels. Only volumes whose histogram fills that few
// bins, none beside another, are scanned.
constexpr int kMaxLabels = 16;
std::vector<double> labelValues(const Volume& volume) {
  const std::vector<uint64_t>& h = volume.histogram();
  if (std::count_if(h.begin(), h.end(), [](uint64_t c) { return c > 0; }) > kMaxLabels) return {};
  for (size_t b = 1; b < h.size(); ++b)
    if (h[b] > 0 && h[b - 1] > 0) return {};
  std::vector<double> values;
  for (int64_t n = 0; n < volume.voxelCount(); ++n) {
    const double v = volume.valueAt(n);
    if (!std::isfinite(v) || std::find(values.begin(), values.end(), v) != values.end()) continue;
    if (int(values.size()) == kMaxLabels) return {};
    values.push_back(v);
  }
  std::sort(values.begin(), values.end());
  return values;
}

// Labels and masks: the most common value (the background) transparent, every other value
// opaque from a quarter of the way to it (rising from a twentieth), each in a colour of its
// own. The post-classified field of a structure one voxel thin peaks at about a third of its
// value (a Gaussian kernel's weighted mean over its neighbours), so opacity that starts only at
// the label value would erase it.
TransferFunction labelTransferFunction(const Volume& volume, const std::vector<double>& labels) {
  static const glm::dvec3 kPalette[] = {{0.95, 0.85, 0.70}, {0.90, 0.35, 0.25}, {0.30, 0.60, 0.90},
                                        {0.45, 0.80, 0.35}, {0.95, 0.75, 0.20}, {0.70, 0.40, 0.85},
                                        {0.30, 0.80, 0.80}, {0.90, 0.55, 0.70}};
  TransferFunction tf;
  const glm::dvec3 spacing = volume.spacing();
  tf.opacityUnitDistance = std::min({spacing.x, spacing.y, spacing.z});
  const std::vector<uint64_t>& h = volume.histogram();
  const double lo = volume.minValue(), hi = volume.maxValue();
  const int mode = int(std::max_element(h.begin(), h.end()) - h.begin());
  const double modeCentre = lo + (mode + 0.5) * (hi - lo) / double(h.size());
  const size_t bg =
      size_t(std::min_element(labels.begin(), labels.end(),
                              [&](double a, double b) {
                                return std::abs(a - modeCentre) < std::abs(b - modeCentre);
                              }) -
             labels.begin());
  // Clear for the first 5% about the background, so that the background's own values (and the
  // table bin holding them) stay transparent and its voxels are no splats.
  constexpr double kOpacity = 0.7, kClear = 0.05, kOpaque = 0.25;
  const double b = labels[bg];
  tf.opacity.push_back({b, 0.0});
  if (bg > 0) {
    const double gap = b - labels[bg - 1];
    tf.opacity.push_back({b - kClear * gap, 0.0});
    tf.opacity.push_back({b - kOpaque * gap, kOpacity});
  }
  if (bg + 1 < labels.size()) {
    const double gap = labels[bg + 1] - b;
    tf.opacity.push_back({b + kClear * gap, 0.0});
    tf.opacity.push_back({b + kOpaque * gap, kOpacity});
  }
  size_t colour = 0;
  tf.color.push_back({b, kPalette[0]});
  for (size_t n = 0; n < labels.size(); ++n)
    if (n != bg) tf.color.push_back({labels[n], kPalette[colour++ % std::size(kPalette)]});
  tf.sortPoints();
  return tf;
}

}  // namespace

TransferFunction defaultTransferFunction(const Volume& volume) {
  TransferFunction tf;
  const glm::dvec3 spacing = volume.spacing();
  tf.opacityUnitDistance = std::min({spacing.x, spacing.y, spacing.z});
  const double lo = volume.minValue();
  const double hi = volume.maxValue();
  const glm::dvec3 dark(0.55, 0.22, 0.12), warm(0.92, 0.58, 0.32), ivory(1.0, 0.96, 0.88);
  if (volume.empty() || !(hi > lo)) {
    // Nothing to tell apart: a faint fog so the extent is still visible.
    tf.opacity = {{lo, 0.02}};
    tf.color = {{lo, warm}};
    return tf;
  }
  if (const std::vector<double> labels = labelValues(volume); labels.size() >= 2)
    return labelTransferFunction(volume, labels);
  const std::vector<uint64_t>& h = volume.histogram();
  const double width = (hi - lo) / double(h.size());
  const std::vector<double> s = smoothHistogram(h);
  const int mode = int(std::max_element(h.begin(), h.end()) - h.begin());
  int end = backgroundEnd(s, mode);
  if (end >= int(h.size()) - 2) end = 0;  // the background fills the range: ramp over all of it
  // A background (air, an empty field) is the low end of the values; a mode with most voxels
  // below it is a material, in a volume cropped to its object (NiBabel's anatomical.nii, an MR
  // with no air, was left with its upper 1% visible): ramp over the whole range.
  if (shareBelow(h, mode) > 0.5) end = 0;
  const double threshold = lo + (end + 1) * width;
  const double median = quantile(h, end + 1, 0.5, lo, width);
  const double upper = quantile(h, end + 1, 0.95, lo, width);
  tf.opacity = {{threshold, 0.0}, {median, 0.015}, {upper, 0.25}, {hi, 0.6}};
  tf.color = {{threshold, dark}, {median, warm}, {hi, ivory}};
  tf.sortPoints();
  return tf;
}

}  // namespace ewa
