// ShearWarpVolume: table coordinates, cell ranges by separable min/max, per-axis slices and runs.
#include "core/shear_warp_volume.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ewa {

namespace {

// In-place running min (or max) along one axis of an x-fastest grid over [x, x + reach]
// (step +1) or [x - reach, x] (step -1), clamped at the ends: a separable pass of a box filter.
template <typename Op>
void extend(std::vector<uint8_t>& a, const std::array<int64_t, 3>& d, int axis, int reach, int step,
            Op op) {
  const int64_t stride = axis == 0 ? 1 : axis == 1 ? d[0] : d[0] * d[1];
  const int64_t n = d[axis];
  const int64_t total = d[0] * d[1] * d[2];
  std::vector<uint8_t> line(n);
  for (int64_t outer = 0; outer < total; outer += stride * n)
    for (int64_t base = outer; base < outer + stride; ++base) {
      for (int64_t x = 0; x < n; ++x) line[x] = a[base + x * stride];
      for (int64_t x = 0; x < n; ++x) {
        uint8_t v = line[x];
        for (int r = 1; r <= reach; ++r) {
          const int64_t y = x + int64_t(step) * r;
          if (y < 0 || y >= n) break;
          v = op(v, line[y]);
        }
        a[base + x * stride] = v;
      }
    }
}

const auto kMin = [](uint8_t a, uint8_t b) { return std::min(a, b); };
const auto kMax = [](uint8_t a, uint8_t b) { return std::max(a, b); };

}  // namespace

void ShearWarpVolume::setVolume(const Volume& volume, double lo, double hi, int tableSize) {
  if (tableSize < 2 || tableSize > 256)
    throw std::invalid_argument("shear-warp: table size must lie in [2, 256]");
  *this = ShearWarpVolume();
  tableSize_ = tableSize;
  dims_ = volume.dims();
  voxels_ = volume.voxelCount();
  if (volume.empty()) {
    voxels_ = 0;
    return;
  }
  const double top = tableSize - 1;
  const double scale = hi > lo ? top / (hi - lo) : 0.0;
  coords_.resize(voxels_);
  cellLo_.resize(voxels_);
  cellHi_.resize(voxels_);
  for (int64_t n = 0; n < voxels_; ++n) {
    const double v = volume.valueAt(n);
    double t = std::isnan(v) ? 0.0 : std::clamp((v - lo) * scale, 0.0, top);
    coords_[n] = float(t);
    cellLo_[n] = uint8_t(std::floor(coords_[n]));
    cellHi_[n] = uint8_t(std::ceil(coords_[n]));
  }
  // Cell (x, y, z) spans voxels x..x+1, y..y+1, z..z+1.
  for (int axis = 0; axis < 3; ++axis) {
    extend(cellLo_, dims_, axis, 1, +1, kMin);
    extend(cellHi_, dims_, axis, 1, +1, kMax);
  }
  // Wide cells span x-1..x+2: the cells x-1..x+1.
  wideLo_ = cellLo_;
  wideHi_ = cellHi_;
  for (int axis = 0; axis < 3; ++axis) {
    extend(wideLo_, dims_, axis, 1, +1, kMin);
    extend(wideLo_, dims_, axis, 1, -1, kMin);
    extend(wideHi_, dims_, axis, 1, +1, kMax);
    extend(wideHi_, dims_, axis, 1, -1, kMax);
  }
}

void ShearWarpVolume::setVisibility(const std::vector<uint8_t>& visibleBins) {
  if (int(visibleBins.size()) != tableSize_ - 1)
    throw std::invalid_argument("shear-warp: one visibility flag per table interval expected");
  visiblePrefix_.assign(visibleBins.size() + 1, 0);
  for (size_t m = 0; m < visibleBins.size(); ++m)
    visiblePrefix_[m + 1] = visiblePrefix_[m] + (visibleBins[m] ? 1 : 0);
  runsBuilt_ = {};
  if (empty()) return;
  const std::vector<uint8_t> v = cellVisibility(false);
  size_t count = 0;
  for (uint8_t x : v) count += x;
  visibleFraction_ = double(count) / double(v.size());
}

std::vector<uint8_t> ShearWarpVolume::cellVisibility(bool dilated) const {
  const std::vector<uint8_t>& lo = dilated ? wideLo_ : cellLo_;
  const std::vector<uint8_t>& hi = dilated ? wideHi_ : cellHi_;
  std::vector<uint8_t> visible(voxels_, 1);
  if (visiblePrefix_.empty()) return visible;
  const int bins = tableSize_ - 1;
  for (int64_t n = 0; n < voxels_; ++n) {
    // Intervals [a, b): a constant coordinate a touches the intervals on both sides of it.
    int a = lo[n], b = hi[n];
    if (a == b) {
      a = std::max(0, a - 1);
      b = std::min(bins, b + 1);
    }
    visible[n] = visiblePrefix_[b] - visiblePrefix_[a] > 0;
  }
  return visible;
}

const std::vector<float>& ShearWarpVolume::slices(int p) {
  std::vector<float>& s = slices_[p];
  if (!s.empty() || empty()) return s;
  const int ai = (p + 1) % 3, aj = (p + 2) % 3;
  const int64_t stride[3] = {1, dims_[0], dims_[0] * dims_[1]};
  const int64_t w = dims_[ai], h = dims_[aj], d = dims_[p];
  s.resize(voxels_);
  size_t out = 0;
  for (int64_t k = 0; k < d; ++k)
    for (int64_t j = 0; j < h; ++j) {
      const float* src = coords_.data() + k * stride[p] + j * stride[aj];
      for (int64_t i = 0; i < w; ++i) s[out++] = src[i * stride[ai]];
    }
  return s;
}

const CellRuns& ShearWarpVolume::runs(int p, bool dilated) {
  CellRuns& r = runs_[p][dilated];
  if (runsBuilt_[p][dilated]) return r;
  runsBuilt_[p][dilated] = true;
  r = CellRuns();
  if (empty()) return r;
  const int ai = (p + 1) % 3, aj = (p + 2) % 3;
  const int64_t stride[3] = {1, dims_[0], dims_[0] * dims_[1]};
  const int64_t w = dims_[ai], h = dims_[aj], d = dims_[p];
  const int64_t cells = std::max<int64_t>(0, w - 1);
  r.rows = int(std::max<int64_t>(0, h - 1));
  r.offsets.assign(size_t(d) * r.rows + 1, 0);
  const std::vector<uint8_t> visible = cellVisibility(dilated);
  for (int64_t k = 0; k < d; ++k)
    for (int64_t j = 0; j < r.rows; ++j) {
      const uint8_t* row = visible.data() + k * stride[p] + j * stride[aj];
      int64_t i = 0;
      while (i < cells) {
        while (i < cells && !row[i * stride[ai]]) ++i;
        const int64_t first = i;
        while (i < cells && row[i * stride[ai]]) ++i;
        if (i > first) r.runs.push_back({int32_t(first), int32_t(i)});
      }
      r.offsets[size_t(k) * r.rows + j + 1] = int32_t(r.runs.size());
    }
  return r;
}

}  // namespace ewa
