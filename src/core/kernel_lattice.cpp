// Lattice sums of windowed Gaussian footprints, for choosing the kernel width by its ripple.
#include "core/kernel_lattice.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/ewa_footprint.h"

namespace ewa {

LatticeRipple latticeRipple(double width, double cutoff, double lowPass, int samples) {
  const double variance = width * width + std::max(0.0, lowPass);
  // The renderer's normalization: the 2D integral is pi sqrt(det) windowIntegral(c).
  const double norm = 1.0 / (M_PI * variance * windowIntegral(cutoff));
  const int reach = int(std::ceil(std::sqrt(cutoff * variance))) + 1;
  const int n = std::max(1, samples);
  double lo = INFINITY, hi = -INFINITY, sum = 0.0;
  for (int sy = 0; sy <= n; ++sy) {
    for (int sx = 0; sx <= n; ++sx) {
      const double x = double(sx) / n, y = double(sy) / n;
      double total = 0.0;
      for (int j = -reach; j <= reach + 1; ++j)
        for (int i = -reach; i <= reach + 1; ++i) {
          const double dx = x - i, dy = y - j;
          total += windowedGaussian((dx * dx + dy * dy) / variance, cutoff);
        }
      total *= norm;
      lo = std::min(lo, total);
      hi = std::max(hi, total);
      sum += total;
    }
  }
  LatticeRipple out;
  out.mean = sum / double((n + 1) * (n + 1));
  out.ripple = out.mean > 0.0 ? (hi - lo) / out.mean : INFINITY;
  return out;
}

double narrowestSmoothWidth(double cutoff, double limit, double step) {
  const int count = int(std::floor((kMaxKernelWidth - kMinKernelWidth) / step + 1e-9)) + 1;
  double narrowest = kMaxKernelWidth;
  // From the widest down: the last width before the first one over the limit.
  for (int k = count - 1; k >= 0; --k) {
    const double width = kMinKernelWidth + k * step;
    if (!(latticeRipple(width, cutoff).ripple < limit)) break;
    narrowest = width;
  }
  return narrowest;
}

}  // namespace ewa
