// downsampleVolume: box averaging of factor^3 blocks into a float32 volume.
#include "core/volume_downsample.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

namespace ewa {

int downsampleAxisFactor(int64_t dim, int factor) {
  return int(std::min<int64_t>(factor, std::max<int64_t>(dim, 1)));
}

Volume downsampleVolume(const Volume& v, int factor) {
  if (factor < 1) throw std::invalid_argument("downsample factor must be at least 1");
  if (v.empty()) throw std::invalid_argument("cannot downsample an empty volume");
  const auto& d = v.dims();
  int f[3];
  std::array<int64_t, 3> out{};
  for (int a = 0; a < 3; ++a) {
    f[a] = downsampleAxisFactor(d[a], factor);
    out[a] = (d[a] + f[a] - 1) / f[a];
  }
  // Sums per coarse voxel, filled in one pass over the fine voxels in memory order.
  const size_t count = size_t(out[0] * out[1] * out[2]);
  std::vector<double> sum(count, 0.0);
  std::vector<uint32_t> n(count, 0);
  for (int64_t k = 0; k < d[2]; ++k) {
    const int64_t ck = k / f[2];
    for (int64_t j = 0; j < d[1]; ++j) {
      const int64_t row = out[0] * ((j / f[1]) + out[1] * ck);
      const int64_t fineRow = v.index(0, j, k);
      for (int64_t i = 0; i < d[0]; ++i) {
        const double value = v.valueAt(fineRow + i);
        if (std::isnan(value)) continue;
        const size_t c = size_t(row + i / f[0]);
        sum[c] += value;
        ++n[c];
      }
    }
  }
  std::vector<uint8_t> bytes(count * sizeof(float));
  for (size_t c = 0; c < count; ++c) {
    const float mean = n[c] ? float(sum[c] / n[c]) : std::numeric_limits<float>::quiet_NaN();
    std::memcpy(bytes.data() + c * sizeof(float), &mean, sizeof(float));
  }
  const glm::dvec3 scale(f[0], f[1], f[2]);
  // The first block's centre, moved along the volume's own axes.
  const glm::dvec3 origin = v.origin() + v.direction() * (0.5 * (scale - 1.0) * v.spacing());
  Volume coarse(out, v.spacing() * scale, origin, ScalarType::Float32, std::move(bytes));
  coarse.setDirection(v.direction(), v.patientFrame());
  coarse.setUnit(v.unit());
  // The source's data box, in the coarse indices (fine index i is coarse (i - (f - 1) / 2) / f).
  const DataBox box = v.indexDataBox();
  coarse.setIndexDataBox(
      {(box.low - 0.5 * (scale - 1.0)) / scale, (box.high - 0.5 * (scale - 1.0)) / scale});
  return coarse;
}

}  // namespace ewa
