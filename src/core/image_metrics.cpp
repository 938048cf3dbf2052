// Image comparison metrics: RMSE, PSNR and mean SSIM.
#include "core/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ewa {

namespace {

void requireSameSize(const FloatImage& a, const FloatImage& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw std::invalid_argument("image metrics: images differ in size or channels");
}

// Separable Gaussian blur with clamped borders, used for SSIM's local statistics.
std::vector<double> blur(const std::vector<double>& in, int w, int h,
                         const std::vector<double>& kernel) {
  const int r = int(kernel.size() / 2);
  std::vector<double> tmp(in.size()), out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0.0;
      for (int k = -r; k <= r; ++k) {
        const int xx = std::min(std::max(x + k, 0), w - 1);
        s += kernel[size_t(k + r)] * in[size_t(y) * w + xx];
      }
      tmp[size_t(y) * w + x] = s;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0.0;
      for (int k = -r; k <= r; ++k) {
        const int yy = std::min(std::max(y + k, 0), h - 1);
        s += kernel[size_t(k + r)] * tmp[size_t(yy) * w + x];
      }
      out[size_t(y) * w + x] = s;
    }
  return out;
}

}  // namespace

FloatImage luminanceOf(const FloatImage& image) {
  if (image.channels == 1) return image;
  if (image.channels < 3) throw std::invalid_argument("luminanceOf: need 1, 3 or 4 channels");
  FloatImage out(image.width, image.height, 1);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      out.at(x, y) =
          0.2126f * image.at(x, y, 0) + 0.7152f * image.at(x, y, 1) + 0.0722f * image.at(x, y, 2);
  return out;
}

double rootMeanSquareError(const FloatImage& a, const FloatImage& b,
                           const std::vector<unsigned char>* mask) {
  requireSameSize(a, b);
  const size_t pixels = size_t(a.width) * a.height;
  if (mask && mask->size() != pixels)
    throw std::invalid_argument("rootMeanSquareError: mask size differs from the image");
  double sum = 0.0;
  size_t count = 0;
  for (size_t p = 0; p < pixels; ++p) {
    if (mask && !(*mask)[p]) continue;
    for (int c = 0; c < a.channels; ++c) {
      const double d = double(a.values[p * a.channels + c]) - b.values[p * a.channels + c];
      sum += d * d;
      ++count;
    }
  }
  return count ? std::sqrt(sum / double(count)) : 0.0;
}

double peakSignalToNoiseRatio(double rmse, double peak) {
  if (rmse <= 0.0) return std::numeric_limits<double>::infinity();
  return 20.0 * std::log10(peak / rmse);
}

double structuralSimilarity(const FloatImage& a, const FloatImage& b, double peak) {
  requireSameSize(a, b);
  const FloatImage la = luminanceOf(a), lb = luminanceOf(b);
  const int w = la.width, h = la.height;
  if (w == 0 || h == 0) return 1.0;
  std::vector<double> kernel(11);
  double norm = 0.0;
  for (int k = -5; k <= 5; ++k) norm += kernel[size_t(k + 5)] = std::exp(-k * k / (2 * 1.5 * 1.5));
  for (double& k : kernel) k /= norm;

  const size_t n = size_t(w) * h;
  std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
  for (size_t p = 0; p < n; ++p) {
    x[p] = la.values[p];
    y[p] = lb.values[p];
    xx[p] = x[p] * x[p];
    yy[p] = y[p] * y[p];
    xy[p] = x[p] * y[p];
  }
  const auto mx = blur(x, w, h, kernel), my = blur(y, w, h, kernel);
  const auto sxx = blur(xx, w, h, kernel), syy = blur(yy, w, h, kernel),
             sxy = blur(xy, w, h, kernel);
  const double c1 = (0.01 * peak) * (0.01 * peak), c2 = (0.03 * peak) * (0.03 * peak);
  double total = 0.0;
  for (size_t p = 0; p < n; ++p) {
    const double vx = sxx[p] - mx[p] * mx[p], vy = syy[p] - my[p] * my[p],
                 cxy = sxy[p] - mx[p] * my[p];
    total += ((2 * mx[p] * my[p] + c1) * (2 * cxy + c2)) /
             ((mx[p] * mx[p] + my[p] * my[p] + c1) * (vx + vy + c2));
  }
  return total / double(n);
}

}  // namespace ewa
