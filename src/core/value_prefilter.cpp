// Value prefilter: splat values sharpened by a multiple of the discrete Laplacian.
#include "core/value_prefilter.h"

#include <algorithm>
#include <cmath>

#include "core/parallel_chunks.h"

namespace ewa {

double prefilteredValue(const Volume& volume, int64_t i, int64_t j, int64_t k, double strength) {
  const double v = volume.value(i, j, k);
  if (!(strength > 0.0) || !std::isfinite(v)) return v;
  const auto& d = volume.dims();
  const int64_t p[3] = {i, j, k};
  double laplacian = 0.0;  // 6 v - sum of the neighbours
  for (int axis = 0; axis < 3; ++axis) {
    for (int step : {-1, 1}) {
      int64_t q[3] = {p[0], p[1], p[2]};
      q[axis] += step;
      if (q[axis] < 0 || q[axis] >= d[axis]) continue;  // counts as v: adds 0
      const double u = volume.value(q[0], q[1], q[2]);
      if (std::isfinite(u)) laplacian += v - u;
    }
  }
  return std::clamp(v + strength * laplacian, volume.minValue(), volume.maxValue());
}

void prefilterSplatValues(const Volume& volume, double strength, SplatSet* splats,
                          unsigned threads) {
  if (!(strength > 0.0)) return;
  const double lo = volume.minValue(), hi = volume.maxValue();
  const double width = hi > lo ? hi - lo : 1.0;
  // Each splat's new value reads the volume only: the splats split between the cores.
  parallelChunks(splats->size(), kMinChunkWork, threads, [&](size_t first, size_t last, size_t) {
    for (size_t n = first; n < last; ++n) {
      const PackedSplat& s = splats->splats()[n];
      const double v =
          prefilteredValue(volume, SplatSet::i(s), SplatSet::j(s), SplatSet::k(s), strength);
      splats->setNormalizedValue(n, (v - lo) / width);
    }
  });
}

}  // namespace ewa
