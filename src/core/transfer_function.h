// TransferFunction: piecewise-linear opacity and color by scalar value; a default from a histogram.
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "core/volume.h"

namespace ewa {

// The largest extinction a GPU table holds (bake(), the slab pair table): finite in float with
// room for sums over many splats.
inline constexpr double kMaxBakedExtinction = 1e20;

struct OpacityPoint {
  double value;
  double alpha;  // opacity of a layer opacityUnitDistance thick, in [0, 1]
};

struct ColorPoint {
  double value;
  glm::dvec3 rgb;  // each channel in [0, 1]
};

class TransferFunction {
 public:
  std::vector<OpacityPoint> opacity;  // kept sorted by value (call sortPoints after editing)
  std::vector<ColorPoint> color;      // kept sorted by value
  // Alpha is the opacity of a layer this many world units thick (VTK's scalar-opacity unit
  // distance), so the same function looks the same whatever the voxel spacing.
  double opacityUnitDistance = 1.0;

  // Stable sort of both point lists by value (points with equal values keep their order,
  // which makes a step: the later point wins at and above that value).
  void sortPoints();
  // Throws std::invalid_argument with a message naming the first bad point: non-finite
  // numbers, alpha or color outside [0, 1], unsorted points, unit distance <= 0.
  void validate() const;

  // Piecewise linear, clamped at the ends; 0 if there are no points or the value is NaN.
  double alphaAt(double value) const;
  // Piecewise linear, clamped; white if there are no points, the first color for NaN.
  glm::dvec3 colorAt(double value) const;
  // Extinction coefficient per world unit: tau = -ln(1 - alpha) / opacityUnitDistance, with
  // alpha clamped to [0, 1 - 1e-6] so an opaque point stays finite.
  double extinctionAt(double value) const;
  // n samples over [lo, hi] (sample i at lo + (hi - lo) * i / (n - 1); one sample at lo when
  // n == 1) of (r, g, b, tau) for a GPU texture, tau capped at 1e20 so it stays finite in float.
  // Throws std::invalid_argument for n < 1 or non-finite bounds.
  std::vector<glm::vec4> bake(double lo, double hi, int n) const;
  // True when no value in [lo, hi] has alpha > 0 (nothing would be drawn). Exact: the
  // function is linear between points, so the ends and the points inside decide.
  bool allTransparent(double lo, double hi) const;

  // ---- Editing (what the editor's mouse does). Points stay sorted and valid. ----
  // Inserts a point (alpha and colour clamped to [0, 1]) after any point of equal value and
  // returns its index. Throws std::invalid_argument for non-finite numbers.
  size_t addOpacityPoint(double value, double alpha);
  size_t addColorPoint(double value, const glm::dvec3& rgb);
  // Moves point `index` to (value, alpha): the value is clamped between its neighbours' values
  // (a dragged point never passes another, so its index stays the same) and alpha to [0, 1].
  // Non-finite inputs keep the old coordinate. Throws std::out_of_range for a bad index.
  void moveOpacityPoint(size_t index, double value, double alpha);
  void moveColorPoint(size_t index, double value);
  void setPointColor(size_t index, const glm::dvec3& rgb);  // clamped to [0, 1]
  // Removes point `index`. Throws std::out_of_range for a bad index.
  void removeOpacityPoint(size_t index);
  void removeColorPoint(size_t index);
};

bool operator==(const OpacityPoint& a, const OpacityPoint& b);
bool operator==(const ColorPoint& a, const ColorPoint& b);
bool operator==(const TransferFunction& a, const TransferFunction& b);
inline bool operator!=(const TransferFunction& a, const TransferFunction& b) {
  return !(a == b);
}

// A default for a volume, made from its histogram: transparent over the dominant background
// values, a ramp of opacity above them, a warm bone-like color map, and
// opacityUnitDistance = the smallest spacing. A volume of at most 16 distinct values (a mask,
// labels) gets its most common value transparent and every other value opaque, from a quarter
// of the way to it on, in a colour each, so that structures one voxel thin stay visible.
TransferFunction defaultTransferFunction(const Volume& volume);

}  // namespace ewa
