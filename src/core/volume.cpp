// Volume: native-type storage, statistics and world placement.
#include "core/volume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/common.hpp>
#include <limits>
#include <stdexcept>

#include "core/parallel_chunks.h"

namespace ewa {

const char* scalarName(ScalarType type) {
  switch (type) {
    case ScalarType::UInt8:
      return "uint8";
    case ScalarType::Int16:
      return "int16";
    case ScalarType::UInt16:
      return "uint16";
    case ScalarType::Float32:
      return "float32";
  }
  return "?";
}

Volume::Volume(std::array<int64_t, 3> dims, glm::dvec3 spacing, glm::dvec3 origin, ScalarType type,
               std::vector<uint8_t> bytes)
    : dims_(dims), spacing_(spacing), origin_(origin), type_(type), bytes_(std::move(bytes)) {
  for (int64_t d : dims_) {
    if (d <= 0) throw std::invalid_argument("volume dimensions must be positive");
  }
  setSpacing(spacing);
  const auto count = static_cast<uint64_t>(voxelCount());
  if (bytes_.size() / scalarSize(type_) != count || bytes_.size() % scalarSize(type_) != 0)
    throw std::invalid_argument("volume data size does not match its dimensions");
  computeStatistics();
}

void Volume::setSpacing(const glm::dvec3& spacing) {
  for (int a = 0; a < 3; ++a) {
    if (!(spacing[a] > 0.0) || !std::isfinite(spacing[a]))
      throw std::invalid_argument("volume spacing must be positive and finite");
  }
  spacing_ = spacing;
}

void Volume::setDirection(const glm::dmat3& direction, bool patientFrame) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (!std::isfinite(direction[c][r]))
        throw std::invalid_argument("volume direction must be finite");
  direction_ = direction;
  patientFrame_ = patientFrame;
}

glm::dvec3 Volume::framePosition(double i, double j, double k) const {
  return origin_ + glm::dvec3(i, j, k) * spacing_;
}

glm::dvec3 Volume::worldPosition(double i, double j, double k) const {
  return origin_ + direction_ * (glm::dvec3(i, j, k) * spacing_);
}

glm::dvec3 Volume::boundsMax() const {
  return framePosition(double(dims_[0] - 1), double(dims_[1] - 1), double(dims_[2] - 1));
}

DataBox Volume::indexDataBox() const {
  if (dataBox_) return *dataBox_;
  DataBox box;
  for (int axis = 0; axis < 3; ++axis) {
    const double top = double(std::max<int64_t>(dims_[axis], 1) - 1);
    box.low[axis] = top > 0.0 ? 0.0 : -0.5;
    box.high[axis] = top > 0.0 ? top : 0.5;
  }
  return box;
}

void Volume::setIndexDataBox(const DataBox& box) {
  dataBox_ = box;
}

namespace {

// The histogram bin of value v over [lo, lo + width]: computeStatistics and histogramOf bin
// alike, so bricks' histograms add up to the whole volume's.
int histogramBin(double v, double lo, double width, int bins) {
  return std::clamp(static_cast<int>((v - lo) / width * bins), 0, bins - 1);
}

// The world bounds: lower corner when `upper` is false, else the upper one.
glm::dvec3 worldCornerBound(const Volume& v, bool upper) {
  glm::dvec3 out = v.worldPosition(0, 0, 0);
  const auto& d = v.dims();
  for (int c = 1; c < 8; ++c) {
    const glm::dvec3 p =
        v.worldPosition((c & 1) ? double(d[0] - 1) : 0.0, (c & 2) ? double(d[1] - 1) : 0.0,
                        (c & 4) ? double(d[2] - 1) : 0.0);
    out = upper ? glm::max(out, p) : glm::min(out, p);
  }
  return out;
}

}  // namespace

glm::dvec3 Volume::worldBoundsMin() const {
  return worldCornerBound(*this, false);
}
glm::dvec3 Volume::worldBoundsMax() const {
  return worldCornerBound(*this, true);
}

void Volume::setValueStatistics(double lo, double hi, std::vector<uint64_t> histogram) {
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi) ||
      histogram.size() != size_t(histogramBins()))
    throw std::invalid_argument("a value range lo <= hi and a histogram of 256 bins are needed");
  range_ = {lo, hi};
  histogram_ = std::move(histogram);
}

std::vector<uint64_t> Volume::histogramOf(const std::array<int64_t, 3>& low,
                                          const std::array<int64_t, 3>& high, double lo,
                                          double hi) const {
  const int bins = histogramBins();
  std::vector<uint64_t> h(size_t(bins), 0);
  const double width = hi > lo ? hi - lo : 1.0;
  std::array<int64_t, 3> a, b;
  for (int axis = 0; axis < 3; ++axis) {
    a[axis] = std::max<int64_t>(low[axis], 0);
    b[axis] = std::min(high[axis], dims_[axis]);
  }
  for (int64_t k = a[2]; k < b[2]; ++k)
    for (int64_t j = a[1]; j < b[1]; ++j)
      for (int64_t i = a[0]; i < b[0]; ++i) {
        const double v = value(i, j, k);
        if (std::isfinite(v)) h[size_t(histogramBin(v, lo, width, bins))]++;
      }
  return h;
}

void Volume::computeStatistics() {
  const size_t n = size_t(voxelCount());
  // Range, then histogram, each over chunks of the voxels on the machine's cores: minima,
  // maxima and counts merge to the same result in any order.
  using Range = std::array<double, 2>;
  const std::vector<Range> ranges =
      parallelChunkResults<Range>(n, kMinChunkWork, 0, [&](size_t first, size_t last) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (size_t i = first; i < last; ++i) {
          const double v = valueAt(int64_t(i));
          if (!std::isfinite(v)) continue;
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
        return Range{lo, hi};
      });
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const auto& r : ranges) {
    lo = std::min(lo, r[0]);
    hi = std::max(hi, r[1]);
  }
  if (!(lo <= hi)) lo = hi = 0.0;
  range_ = {lo, hi};
  const double width = hi > lo ? hi - lo : 1.0;
  const int bins = histogramBins();
  using Counts = std::vector<uint64_t>;
  const std::vector<Counts> counts =
      parallelChunkResults<Counts>(n, kMinChunkWork, 0, [&](size_t first, size_t last) {
        Counts h(size_t(bins), 0);
        for (size_t i = first; i < last; ++i) {
          const double v = valueAt(int64_t(i));
          if (!std::isfinite(v)) continue;
          h[size_t(histogramBin(v, lo, width, bins))]++;
        }
        return h;
      });
  histogram_.assign(size_t(bins), 0);
  for (const auto& h : counts)
    for (int b = 0; b < bins; ++b) histogram_[size_t(b)] += h[size_t(b)];
}

}  // namespace ewa
