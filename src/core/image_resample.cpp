// Gaussian low-pass and decimation, separable, with exact output pixel centres.
#include "core/image_resample.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ewa {

namespace {

struct Taps {
  int first = 0;
  std::vector<double> weights;
};

// Filter taps of output pixel `x` over `fineSize` fine pixels: Gaussian in fine pixel units,
// renormalised over the taps that lie inside the image.
Taps tapsFor(int x, int factor, double sigmaFine, int fineSize) {
  const double center = factor * (x + 0.5);
  const int reach = int(std::ceil(4.0 * sigmaFine));
  const int lo = std::max(0, int(std::floor(center)) - reach);
  const int hi = std::min(fineSize - 1, int(std::floor(center)) + reach);
  Taps t;
  t.first = lo;
  double sum = 0.0;
  for (int i = lo; i <= hi; ++i) {
    const double d = (i + 0.5 - center) / sigmaFine;
    t.weights.push_back(std::exp(-0.5 * d * d));
    sum += t.weights.back();
  }
  for (double& w : t.weights) w /= sum;
  return t;
}

}  // namespace

FloatImage gaussianDecimate(const FloatImage& fine, int factor, double sigma) {
  if (factor < 1 || !(sigma > 0.0))
    throw std::invalid_argument("gaussianDecimate: factor must be >= 1 and sigma > 0");
  if (fine.width % factor != 0 || fine.height % factor != 0)
    throw std::invalid_argument("gaussianDecimate: image size is not a multiple of the factor");
  const int w = fine.width / factor, h = fine.height / factor, ch = fine.channels;
  const double sigmaFine = sigma * factor;
  // Horizontal pass: fine rows, output columns.
  FloatImage rows(w, fine.height, ch);
  for (int x = 0; x < w; ++x) {
    const Taps t = tapsFor(x, factor, sigmaFine, fine.width);
    for (int y = 0; y < fine.height; ++y)
      for (int c = 0; c < ch; ++c) {
        double s = 0.0;
        for (size_t k = 0; k < t.weights.size(); ++k)
          s += t.weights[k] * fine.at(t.first + int(k), y, c);
        rows.at(x, y, c) = float(s);
      }
  }
  // Vertical pass.
  FloatImage out(w, h, ch);
  for (int y = 0; y < h; ++y) {
    const Taps t = tapsFor(y, factor, sigmaFine, fine.height);
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < ch; ++c) {
        double s = 0.0;
        for (size_t k = 0; k < t.weights.size(); ++k)
          s += t.weights[k] * rows.at(x, t.first + int(k), c);
        out.at(x, y, c) = float(s);
      }
  }
  return out;
}

FloatImage cropImage(const FloatImage& image, int margin, int width, int height) {
  if (margin < 0 || width < 0 || height < 0 || margin + width > image.width ||
      margin + height > image.height)
    throw std::invalid_argument("cropImage: the crop lies outside the image");
  FloatImage out(width, height, image.channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < image.channels; ++c)
        out.at(x, y, c) = image.at(x + margin, y + margin, c);
  return out;
}

}  // namespace ewa
