// Reference-image comparison for render tests, writing actual and difference images on failure.
#include "image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace ewa::test {

std::string testOutputDir() {
  const std::string dir = EWA_TEST_OUT;
  std::filesystem::create_directories(dir);
  return dir;
}

static Image8 toRgba(const Image8& img) {
  if (img.channels == 4) return img;
  Image8 out{img.width, img.height, 4, std::vector<uint8_t>(size_t(img.width) * img.height * 4)};
  for (size_t p = 0; p < size_t(img.width) * img.height; ++p) {
    for (int c = 0; c < 3; ++c) out.pixels[p * 4 + c] = img.pixels[p * 3 + c];
    out.pixels[p * 4 + 3] = 255;
  }
  return out;
}

::testing::AssertionResult matchesReference(const std::string& name, const Image8& actualIn,
                                            double meanTolerance, int pixelTolerance,
                                            double maxBadFraction) {
  const Image8 actual = toRgba(actualIn);
  const std::string refPath = std::string(EWA_TEST_DIR) + "/reference/" + name + ".png";
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
           << name << ": size " << actual.width << "x" << actual.height << " differs from reference "
           << ref.width << "x" << ref.height << " (actual written to " << actualPath << ")";
  }
  Image8 diff{actual.width, actual.height, 4, std::vector<uint8_t>(actual.pixels.size())};
  double sum = 0.0;
  size_t bad = 0;
  const size_t pixels = size_t(actual.width) * actual.height;
  for (size_t p = 0; p < pixels; ++p) {
    int worst = 0;
    for (int c = 0; c < 4; ++c) {
      const int d = std::abs(int(actual.pixels[p * 4 + c]) - int(ref.pixels[p * 4 + c]));
      sum += d;
      worst = std::max(worst, d);
      diff.pixels[p * 4 + c] = c < 3 ? uint8_t(std::min(255, d * 8)) : 255;
    }
    if (worst > pixelTolerance) ++bad;
  }
  const double mean = sum / double(pixels * 4);
  const double badFraction = double(bad) / double(pixels);
  if (mean <= meanTolerance && badFraction <= maxBadFraction) return ::testing::AssertionSuccess();
  const std::string diffPath = testOutputDir() + "/" + name + ".diff.png";
  writePng(actualPath, actual);
  writePng(diffPath, diff);
  return ::testing::AssertionFailure()
         << name << ": mean difference " << mean << " (tolerance " << meanTolerance << "), "
         << badFraction * 100 << "% of pixels off by more than " << pixelTolerance
         << " (tolerance " << maxBadFraction * 100 << "%); wrote " << actualPath << " and "
         << diffPath;
}

}  // namespace ewa::test
