// Tests of the Gaussian decimation that makes the benchmark's reference, and region statistics.
#include "core/image_resample.h"

#include <gtest/gtest.h>

#include <cmath>

#include "bench/image_statistics.h"

namespace ewa {
namespace {

// A fine image holding f(x, y) at fine pixel centres, in fine pixel units.
template <typename F>
FloatImage fineImage(int w, int h, F f) {
  FloatImage img(w, h, 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y) = float(f(x + 0.5, y + 0.5));
  return img;
}

TEST(GaussianDecimate, KeepsConstantsEverywhereIncludingBorders) {
  const FloatImage out = gaussianDecimate(FloatImage(40, 24, 3, 0.3f), 4, 1.0);
  ASSERT_EQ(out.width, 10);
  ASSERT_EQ(out.height, 6);
  ASSERT_EQ(out.channels, 3);
  for (float v : out.values) EXPECT_NEAR(v, 0.3f, 1e-6);
}

TEST(GaussianDecimate, SamplesLinearRampsAtOutputPixelCentres) {
  // A symmetric filter keeps a linear function, so an interior output pixel (x, y) must hold
  // the ramp at fine coordinate factor * (x + 0.5): this pins the pixel-centre alignment.
  const int factor = 8;
  const FloatImage fine =
      fineImage(32 * factor, 32 * factor, [](double x, double y) { return 0.01 * x + 0.003 * y; });
  const FloatImage out = gaussianDecimate(fine, factor, 1.0);
  for (int y = 5; y < 27; ++y)
    for (int x = 5; x < 27; ++x)
      EXPECT_NEAR(out.at(x, y), 0.01 * factor * (x + 0.5) + 0.003 * factor * (y + 0.5), 1e-4);
}

TEST(GaussianDecimate, AttenuatesASineAsTheGaussianTransferFunction) {
  // A sine of period P output pixels keeps exp(-2 pi^2 sigma^2 / P^2) of its amplitude.
  const int factor = 4;
  const double period = 5.0, sigma = 1.0, kPi = 3.14159265358979323846;
  const FloatImage fine = fineImage(60 * factor, 4 * factor, [&](double x, double) {
    return std::sin(2.0 * kPi * x / (period * factor));
  });
  const FloatImage out = gaussianDecimate(fine, factor, sigma);
  const double gain = std::exp(-2.0 * kPi * kPi * sigma * sigma / (period * period));
  for (int x = 8; x < 52; ++x)
    EXPECT_NEAR(out.at(x, 2), gain * std::sin(2.0 * kPi * (x + 0.5) / period), 2e-3) << x;
}

TEST(GaussianDecimate, RejectsBadArguments) {
  EXPECT_THROW(gaussianDecimate(FloatImage(10, 10, 1), 4, 1.0), std::invalid_argument);
  EXPECT_THROW(gaussianDecimate(FloatImage(8, 8, 1), 0, 1.0), std::invalid_argument);
  EXPECT_THROW(gaussianDecimate(FloatImage(8, 8, 1), 2, 0.0), std::invalid_argument);
}

TEST(CropImage, TakesTheCentre) {
  FloatImage img(6, 5, 1);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 6; ++x) img.at(x, y) = float(10 * y + x);
  const FloatImage c = cropImage(img, 1, 3, 2);
  EXPECT_EQ(c.at(0, 0), 11.0f);
  EXPECT_EQ(c.at(2, 1), 23.0f);
  EXPECT_THROW(cropImage(img, 2, 5, 2), std::invalid_argument);
}

TEST(ImageStatistics, MeanAbsoluteDifferenceOverTheMaskOnly) {
  FloatImage a(2, 1, 1), b(2, 1, 1);
  a.at(0, 0) = 0.5f;
  a.at(1, 0) = 1.0f;  // outside the mask
  EXPECT_DOUBLE_EQ(meanAbsoluteDifference(a, b, {1, 0}), 0.5);
  EXPECT_DOUBLE_EQ(meanAbsoluteDifference(a, b, {0, 0}), 0.0);
  EXPECT_THROW(meanAbsoluteDifference(a, b, {1}), std::invalid_argument);
}

TEST(ImageStatistics, ContrastAndGainSeparateBlurFromNoise) {
  // Reference: alternating 0.2/0.8. Blurred: alternating 0.4/0.6 (a third of the amplitude).
  // Noisy: the reference plus a pattern uncorrelated with it.
  const int n = 64;
  FloatImage ref(n, 1, 1), blurred(n, 1, 1), noisy(n, 1, 1);
  for (int x = 0; x < n; ++x) {
    ref.at(x, 0) = x % 2 ? 0.8f : 0.2f;
    blurred.at(x, 0) = x % 2 ? 0.6f : 0.4f;
    noisy.at(x, 0) = ref.at(x, 0) + ((x / 2) % 2 ? 0.2f : -0.2f);
  }
  const PixelMask all(n, 1);
  EXPECT_NEAR(rmsContrast(ref, all), 0.3, 1e-6);
  EXPECT_NEAR(rmsContrast(blurred, all) / rmsContrast(ref, all), 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(signalGain(blurred, ref, all), 1.0 / 3.0, 1e-6);
  EXPECT_GT(rmsContrast(noisy, all), rmsContrast(ref, all));  // noise raises the contrast...
  EXPECT_NEAR(signalGain(noisy, ref, all), 1.0, 1e-6);        // ...but not the gain
  EXPECT_EQ(maskCount(all), size_t(n));
}

}  // namespace
}  // namespace ewa
