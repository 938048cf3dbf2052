// Reference-image comparison for render tests, writing actual and difference images on failure.
#include "image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace ewa::test {

namespace {
// A pixel counts as covered when it differs from the background by more than this (8-bit
// rounding of the background colour and of faint haze stays out).
constexpr int kCoverage = 2;

uint8_t channel(const Image8& img, size_t pixel, int c) {
  return img.pixels[pixel * size_t(img.channels) + size_t(c)];
}

bool covers(const Image8& img, size_t pixel, const Rgb8& background) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(int(channel(img, pixel, c)) - int(background[size_t(c)])) > kCoverage) return true;
  return false;
}

std::string referencePath(const std::string& name) {
  return std::string(EWA_TEST_DIR) + "/reference/" + name + ".png";
}
}  // namespace

std::string testOutputDir() {
  const std::string dir = EWA_TEST_OUT;
  std::filesystem::create_directories(dir);
  return dir;
}

int maxDifference(const Image8& a, const Image8& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  if (a.pixels.size() != b.pixels.size()) return 255;
  int worst = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    worst = std::max(worst, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
  return worst;
}

double meanValue(const Image8& a) {
  double sum = 0.0;
  for (uint8_t v : a.pixels) sum += v;
  return sum / double(std::max<size_t>(1, a.pixels.size()));
}

Rgb8 backgroundRgb8(double r, double g, double b) {
  auto q = [](double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return {q(r), q(g), q(b)};
}

ImageDifference compareCovered(const Image8& a, const Image8& b, const Rgb8& background,
                               int pixelTolerance) {
  ImageDifference d;
  if (a.width != b.width || a.height != b.height) {
    d.mean = 255.0;
    d.badFraction = 1.0;
    return d;
  }
  double sum = 0.0;
  size_t bad = 0;
  const size_t pixels = size_t(a.width) * a.height;
  for (size_t p = 0; p < pixels; ++p) {
    if (!covers(a, p, background) && !covers(b, p, background)) continue;
    ++d.covered;
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int diff = std::abs(int(channel(a, p, c)) - int(channel(b, p, c)));
      sum += diff;
      worst = std::max(worst, diff);
    }
    if (worst > pixelTolerance) ++bad;
  }
  if (d.covered > 0) {
    d.mean = sum / double(d.covered * 3);
    d.badFraction = double(bad) / double(d.covered);
  }
  return d;
}

Image8 readReference(const std::string& name) {
  return readPng(referencePath(name));
}

::testing::AssertionResult matchesReference(const std::string& name, const Image8& actual,
                                            const Rgb8& background, double meanTolerance,
                                            int pixelTolerance, double maxBadFraction) {
  const std::string refPath = referencePath(name);
  const char* update = std::getenv("EWA_UPDATE_REFERENCES");
  if (update && std::string(update) == "1") {
    std::filesystem::create_directories(std::string(EWA_TEST_DIR) + "/reference");
    writePng(refPath, actual);
    return ::testing::AssertionSuccess() << "reference written: " << refPath;
  }
  const std::string actualPath = testOutputDir() + "/" + name + ".actual.png";
  Image8 ref;
  try {
    ref = readPng(refPath);
  } catch (const std::exception& e) {
    writePng(actualPath, actual);
    return ::testing::AssertionFailure() << e.what() << " (actual written to " << actualPath << ")";
  }
  if (ref.width != actual.width || ref.height != actual.height) {
    writePng(actualPath, actual);
    return ::testing::AssertionFailure()
           << name << ": size " << actual.width << "x" << actual.height
           << " differs from reference " << ref.width << "x" << ref.height << " (actual written to "
           << actualPath << ")";
  }
  const ImageDifference d = compareCovered(actual, ref, background, pixelTolerance);
  if (d.covered > 0 && d.mean <= meanTolerance && d.badFraction <= maxBadFraction)
    return ::testing::AssertionSuccess();
  const size_t pixels = size_t(actual.width) * actual.height;
  Image8 diff{actual.width, actual.height, 3, std::vector<uint8_t>(pixels * 3)};
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c)
      diff.pixels[p * 3 + size_t(c)] = uint8_t(
          std::min(255, 8 * std::abs(int(channel(actual, p, c)) - int(channel(ref, p, c)))));
  const std::string diffPath = testOutputDir() + "/" + name + ".diff.png";
  writePng(actualPath, actual);
  writePng(diffPath, diff);
  if (d.covered == 0)
    return ::testing::AssertionFailure() << name << ": nothing drawn (every pixel is background); "
                                         << "wrote " << actualPath;
  return ::testing::AssertionFailure()
         << name << ": mean RGB difference " << d.mean << " over the " << d.covered
         << " covered pixels (tolerance " << meanTolerance << "), " << d.badFraction * 100
         << "% of them off by more than " << pixelTolerance << " (tolerance "
         << maxBadFraction * 100 << "%); wrote " << actualPath << " and " << diffPath;
}

}  // namespace ewa::test
