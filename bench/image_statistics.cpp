// Region statistics: masked mean absolute difference, RMS contrast, regression gain.
#include "bench/image_statistics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ewa {

namespace {

void requireMask(const FloatImage& image, const PixelMask& mask, const char* who) {
  if (mask.size() != size_t(image.width) * image.height)
    throw std::invalid_argument(std::string(who) + ": mask size differs from the image");
}

}  // namespace

size_t maskCount(const PixelMask& mask) {
  size_t n = 0;
  for (unsigned char m : mask) n += m != 0;
  return n;
}

double meanAbsoluteDifference(const FloatImage& a, const FloatImage& b, const PixelMask& mask) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw std::invalid_argument("meanAbsoluteDifference: images differ in size or channels");
  requireMask(a, mask, "meanAbsoluteDifference");
  double sum = 0.0;
  size_t n = 0;
  for (size_t p = 0; p < mask.size(); ++p) {
    if (!mask[p]) continue;
    for (int c = 0; c < a.channels; ++c) {
      const size_t i = p * a.channels + c;
      sum += std::abs(double(a.values[i]) - double(b.values[i]));
    }
    n += a.channels;
  }
  return n ? sum / double(n) : 0.0;
}

double rmsContrast(const FloatImage& image, const PixelMask& mask) {
  requireMask(image, mask, "rmsContrast");
  const FloatImage lum = luminanceOf(image);
  double sum = 0.0, sum2 = 0.0;
  size_t n = 0;
  for (size_t p = 0; p < mask.size(); ++p) {
    if (!mask[p]) continue;
    sum += lum.values[p];
    sum2 += double(lum.values[p]) * lum.values[p];
    ++n;
  }
  if (n == 0) return 0.0;
  const double mean = sum / double(n);
  return std::sqrt(std::max(0.0, sum2 / double(n) - mean * mean));
}

double signalGain(const FloatImage& image, const FloatImage& reference, const PixelMask& mask) {
  if (image.width != reference.width || image.height != reference.height)
    throw std::invalid_argument("signalGain: images differ in size");
  requireMask(image, mask, "signalGain");
  const FloatImage a = luminanceOf(image), r = luminanceOf(reference);
  double ma = 0.0, mr = 0.0;
  size_t n = 0;
  for (size_t p = 0; p < mask.size(); ++p)
    if (mask[p]) ma += a.values[p], mr += r.values[p], ++n;
  if (n == 0) return 0.0;
  ma /= double(n);
  mr /= double(n);
  double cov = 0.0, var = 0.0;
  for (size_t p = 0; p < mask.size(); ++p) {
    if (!mask[p]) continue;
    const double da = a.values[p] - ma, dr = r.values[p] - mr;
    cov += da * dr;
    var += dr * dr;
  }
  return var > 0.0 ? cov / var : 0.0;
}

}  // namespace ewa
