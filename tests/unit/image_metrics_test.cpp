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
