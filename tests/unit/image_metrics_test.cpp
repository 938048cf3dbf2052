// Tests of RMSE, PSNR and SSIM against hand-computed values.
#include "core/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "io/image_convert.h"

namespace ewa {
namespace {

FloatImage ramp(int w, int h) {
  FloatImage img(w, h, 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y) = float((x * 7 + y * 3) % 17) / 16.0f;
  return img;
}

TEST(ImageMetrics, RmseOfConstantOffset) {
  FloatImage a(8, 4, 3, 0.25f), b(8, 4, 3, 0.75f);
  EXPECT_NEAR(rootMeanSquareError(a, b), 0.5, 1e-9);
  EXPECT_NEAR(peakSignalToNoiseRatio(0.5, 1.0), 20.0 * std::log10(2.0), 1e-9);
  EXPECT_TRUE(std::isinf(peakSignalToNoiseRatio(0.0, 1.0)));
}

TEST(ImageMetrics, RmseRespectsMask) {
  FloatImage a(2, 1, 1), b(2, 1, 1);
  b.at(0, 0) = 1.0f;  // differs only in pixel 0
  std::vector<unsigned char> onlySecond = {0, 1}, onlyFirst = {1, 0};
  EXPECT_DOUBLE_EQ(rootMeanSquareError(a, b, &onlySecond), 0.0);
  EXPECT_DOUBLE_EQ(rootMeanSquareError(a, b, &onlyFirst), 1.0);
  EXPECT_NEAR(rootMeanSquareError(a, b), std::sqrt(0.5), 1e-12);
}

TEST(ImageMetrics, SizeMismatchThrows) {
  EXPECT_THROW(rootMeanSquareError(FloatImage(2, 2, 1), FloatImage(2, 3, 1)),
               std::invalid_argument);
  EXPECT_THROW(structuralSimilarity(FloatImage(2, 2, 1), FloatImage(2, 2, 3), 1.0),
               std::invalid_argument);
}

TEST(ImageMetrics, SsimIsOneForIdenticalAndDropsWithNoise) {
  const FloatImage a = ramp(32, 24);
  EXPECT_NEAR(structuralSimilarity(a, a, 1.0), 1.0, 1e-12);
  FloatImage noisy = a;
  for (size_t i = 0; i < noisy.values.size(); ++i) noisy.values[i] += (i % 2 ? 0.2f : -0.2f);
  const double s = structuralSimilarity(a, noisy, 1.0);
  EXPECT_LT(s, 0.9);
  EXPECT_GT(s, 0.0);
  // A uniform brightness shift hurts SSIM far less than noise of the same RMSE.
  FloatImage shifted = a;
  for (float& v : shifted.values) v += 0.2f;
  EXPECT_GT(structuralSimilarity(a, shifted, 1.0), s);
}

// SSIM on pairs whose value is known in closed form (C1 = (0.01 L)^2, C2 = (0.03 L)^2, L = 1):
// the shear-warp test's SSIM > 0.99 threshold means something only if these hold.
FloatImage pattern(int w, int h, float (*value)(int x, int y)) {
  FloatImage img(w, h, 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y) = value(x, y);
  return img;
}

TEST(ImageMetrics, SsimOfIdenticalImagesIsOne) {
  FloatImage a(64, 48, 3);
  for (size_t i = 0; i < a.values.size(); ++i)
    a.values[i] = float((i * 2654435761u) % 1000) / 999.0f;
  EXPECT_NEAR(structuralSimilarity(a, a, 1.0), 1.0, 1e-12);
}

TEST(ImageMetrics, SsimOfTwoConstantsIsTheLuminanceTerm) {
  // No variance anywhere: SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1) exactly.
  const FloatImage a(40, 30, 1, 0.4f), b(40, 30, 1, 0.6f);
  const double c1 = 1e-4, expected = (2 * 0.4 * 0.6 + c1) / (0.16 + 0.36 + c1);
  EXPECT_NEAR(structuralSimilarity(a, b, 1.0), expected, 1e-6);  // 0.9231
}

TEST(ImageMetrics, SsimOfAConstantAndItsNoisedCopyIsC2OverNoisePlusC2) {
  // b = 0.5 +- delta in a checkerboard: the same local mean, local variance delta^2 (the
  // Gaussian window's mean of +-1 alternating is 1.5e-5), no covariance with the constant:
  // SSIM = C2 / (delta^2 + C2). 192 px, so the clamped borders (5 px) change it by < 0.005.
  const FloatImage a(192, 192, 1, 0.5f);
  const FloatImage coarse =
      pattern(192, 192, [](int x, int y) { return 0.5f + ((x + y) % 2 ? 0.03f : -0.03f); });
  EXPECT_NEAR(structuralSimilarity(a, coarse, 1.0), 0.0009 / (0.0009 + 0.0009), 0.005);  // 0.5
  const FloatImage fine =
      pattern(192, 192, [](int x, int y) { return 0.5f + ((x + y) % 2 ? 0.003f : -0.003f); });
  EXPECT_NEAR(structuralSimilarity(a, fine, 1.0), 0.0009 / (0.000009 + 0.0009), 0.002);  // 0.990
}

TEST(ImageMetrics, SsimOfShiftedStripesFollowsTheirCovariance) {
  // Stripes 0.5 + A (1, 0, -1, 0) along x (period 4): each image has local variance A^2/2
  // (the window's mean of the pattern is 6% of A, which changes the variance by < 1%), and a
  // shift by s pixels has covariance (A^2/2) cos(pi s/2): SSIM = (A^2 cos(pi s/2) + C2) /
  // (A^2 + C2) with A = 0.1: 1, 0.0826 and -0.835 for s = 0, 1, 2.
  const double a2 = 0.01, c2 = 0.0009;
  auto stripes = [](int s) {
    FloatImage img(160, 160, 1);
    static const float p[4] = {1.0f, 0.0f, -1.0f, 0.0f};
    for (int y = 0; y < 160; ++y)
      for (int x = 0; x < 160; ++x) img.at(x, y) = 0.5f + 0.1f * p[(x + s) % 4];
    return img;
  };
  const FloatImage base = stripes(0);
  EXPECT_NEAR(structuralSimilarity(base, stripes(4), 1.0), 1.0, 1e-12);
  EXPECT_NEAR(structuralSimilarity(base, stripes(1), 1.0), c2 / (a2 + c2), 0.01);
  EXPECT_NEAR(structuralSimilarity(base, stripes(2), 1.0), (-a2 + c2) / (a2 + c2), 0.01);
}

TEST(ImageMetrics, LuminanceWeightsSumToOne) {
  FloatImage rgb(1, 1, 3);
  rgb.at(0, 0, 0) = rgb.at(0, 0, 1) = rgb.at(0, 0, 2) = 0.5f;
  EXPECT_NEAR(luminanceOf(rgb).at(0, 0), 0.5f, 1e-6f);
  rgb.at(0, 0, 1) = 0.0f;
  EXPECT_NEAR(luminanceOf(rgb).at(0, 0), 0.5f * (0.2126f + 0.0722f), 1e-6f);
}

TEST(ImageConvert, RoundTripsThroughFloat) {
  Image8 img;
  img.width = 2;
  img.height = 1;
  img.channels = 3;
  img.pixels = {0, 128, 255, 10, 20, 30};
  const Image8 back = toImage8(toFloatImage(img));
  EXPECT_EQ(back.pixels, img.pixels);
  FloatImage gray(1, 1, 1, 2.0f);  // out of range clamps
  EXPECT_EQ(toImage8(gray).pixels, (std::vector<uint8_t>{255, 255, 255}));
}

}  // namespace
}  // namespace ewa
