// Image comparison metrics (RMSE, PSNR, SSIM) on float images, for tests and benchmarks.
#pragma once

#include <cstddef>
#include <vector>

namespace ewa {

// A float image, row-major, top row first, channels interleaved.
struct FloatImage {
  int width = 0;
  int height = 0;
  int channels = 1;
  std::vector<float> values;

  FloatImage() = default;
  FloatImage(int w, int h, int c, float fill = 0.0f)
      : width(w), height(h), channels(c), values(std::size_t(w) * h * c, fill) {}
  float& at(int x, int y, int c = 0) { return values[(std::size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c = 0) const {
    return values[(std::size_t(y) * width + x) * channels + c];
  }
};

// Rec. 709 luminance of an RGB(A) image; a one-channel image is returned as it is.
FloatImage luminanceOf(const FloatImage& image);

// Root-mean-square difference over every pixel and channel. Throws std::invalid_argument when
// the sizes differ. `mask` (optional, one value a pixel, nonzero = counted) limits the region.
double rootMeanSquareError(const FloatImage& a, const FloatImage& b,
                           const std::vector<unsigned char>* mask = nullptr);
// 20 log10(peak / rmse); +infinity for identical images.
double peakSignalToNoiseRatio(double rmse, double peak);
// Mean structural similarity (Wang et al. 2004) of the luminances: 11x11 Gaussian window of
// sigma 1.5, K1 = 0.01, K2 = 0.03, dynamic range `peak`. 1 for identical images.
double structuralSimilarity(const FloatImage& a, const FloatImage& b, double peak);

}  // namespace ewa
