// Unit tests of TransferFunction: interpolation, extinction, baking, validation, the default.
#include "core/transfer_function.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

namespace ewa {
namespace {

TransferFunction ramp() {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {10.0, 0.5}, {20.0, 1.0}};
  tf.color = {{0.0, {1.0, 0.0, 0.0}}, {10.0, {0.0, 0.0, 1.0}}};
  return tf;
}

TEST(TransferFunction, AlphaIsPiecewiseLinearAndClamped) {
  const TransferFunction tf = ramp();
  EXPECT_DOUBLE_EQ(tf.alphaAt(0.0), 0.0);
  EXPECT_DOUBLE_EQ(tf.alphaAt(10.0), 0.5);
  EXPECT_DOUBLE_EQ(tf.alphaAt(20.0), 1.0);
  EXPECT_DOUBLE_EQ(tf.alphaAt(5.0), 0.25);
  EXPECT_DOUBLE_EQ(tf.alphaAt(12.5), 0.625);
  EXPECT_DOUBLE_EQ(tf.alphaAt(-100.0), 0.0);
  EXPECT_DOUBLE_EQ(tf.alphaAt(1e9), 1.0);
  EXPECT_DOUBLE_EQ(tf.alphaAt(std::nan("")), 0.0);
}

TEST(TransferFunction, ColorIsPiecewiseLinearAndClamped) {
  const TransferFunction tf = ramp();
  const glm::dvec3 mid = tf.colorAt(2.5);
  EXPECT_DOUBLE_EQ(mid.r, 0.75);
  EXPECT_DOUBLE_EQ(mid.g, 0.0);
  EXPECT_DOUBLE_EQ(mid.b, 0.25);
  EXPECT_EQ(tf.colorAt(-1.0), glm::dvec3(1.0, 0.0, 0.0));
  EXPECT_EQ(tf.colorAt(15.0), glm::dvec3(0.0, 0.0, 1.0));
}

TEST(TransferFunction, EmptyIsTransparentWhite) {
  const TransferFunction tf;
  EXPECT_EQ(tf.alphaAt(3.0), 0.0);
  EXPECT_EQ(tf.colorAt(3.0), glm::dvec3(1.0));
  EXPECT_EQ(tf.extinctionAt(3.0), 0.0);
  EXPECT_TRUE(tf.allTransparent(-1e9, 1e9));
  EXPECT_NO_THROW(tf.validate());
}

TEST(TransferFunction, EqualValuesMakeAStep) {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {5.0, 0.0}, {5.0, 0.8}, {10.0, 0.8}};
  EXPECT_DOUBLE_EQ(tf.alphaAt(4.999), 0.0);
  EXPECT_DOUBLE_EQ(tf.alphaAt(5.0), 0.8);
  EXPECT_DOUBLE_EQ(tf.alphaAt(7.0), 0.8);
}

TEST(TransferFunction, ExtinctionFollowsUnitDistance) {
  TransferFunction tf = ramp();
  tf.opacityUnitDistance = 2.0;
  EXPECT_DOUBLE_EQ(tf.extinctionAt(10.0), -std::log(1.0 - 0.5) / 2.0);
  EXPECT_DOUBLE_EQ(tf.extinctionAt(5.0), -std::log(1.0 - 0.25) / 2.0);
  EXPECT_DOUBLE_EQ(tf.extinctionAt(0.0), 0.0);
  // Opaque points are clamped to 1 - 1e-6 so tau stays finite.
  EXPECT_NEAR(tf.extinctionAt(20.0), -std::log(1e-6) / 2.0, 1e-6);
  // A layer of unit-distance thickness has the point's alpha again.
  EXPECT_NEAR(1.0 - std::exp(-tf.extinctionAt(12.0) * 2.0), tf.alphaAt(12.0), 1e-12);
}

TEST(TransferFunction, BakeSamplesTheRange) {
  const TransferFunction tf = ramp();
  const std::vector<glm::vec4> table = tf.bake(0.0, 20.0, 5);
  ASSERT_EQ(table.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    const double v = 5.0 * i;
    EXPECT_FLOAT_EQ(table[i].r, float(tf.colorAt(v).r));
    EXPECT_FLOAT_EQ(table[i].b, float(tf.colorAt(v).b));
    EXPECT_FLOAT_EQ(table[i].a, float(tf.extinctionAt(v)));
  }
  EXPECT_FLOAT_EQ(table[1].r, 0.5f);
  EXPECT_FLOAT_EQ(table[1].a, float(-std::log(0.75)));
  const std::vector<glm::vec4> one = tf.bake(10.0, 20.0, 1);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_FLOAT_EQ(one[0].a, float(std::log(2.0)));
  EXPECT_THROW(tf.bake(0.0, 1.0, 0), std::invalid_argument);
  EXPECT_THROW(tf.bake(0.0, std::numeric_limits<double>::infinity(), 4), std::invalid_argument);
}

TEST(TransferFunction, AllTransparentLooksInsideTheRange) {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {10.0, 0.0}, {15.0, 0.4}, {20.0, 0.0}};
  EXPECT_TRUE(tf.allTransparent(0.0, 10.0));
  EXPECT_TRUE(tf.allTransparent(-5.0, 3.0));
  EXPECT_TRUE(tf.allTransparent(25.0, 30.0));
  EXPECT_FALSE(tf.allTransparent(0.0, 30.0));  // ends are 0, the point at 15 is not
  EXPECT_FALSE(tf.allTransparent(11.0, 12.0));
  EXPECT_FALSE(tf.allTransparent(12.0, 11.0));
}

TEST(TransferFunction, SortPointsIsStable) {
  TransferFunction tf;
  tf.opacity = {{5.0, 0.1}, {1.0, 0.2}, {5.0, 0.3}, {3.0, 0.4}};
  tf.color = {{2.0, glm::dvec3(0.2)}, {-1.0, glm::dvec3(0.1)}};
  EXPECT_THROW(tf.validate(), std::invalid_argument);
  tf.sortPoints();
  ASSERT_EQ(tf.opacity.size(), 4u);
  EXPECT_EQ(tf.opacity[0].value, 1.0);
  EXPECT_EQ(tf.opacity[1].value, 3.0);
  EXPECT_EQ(tf.opacity[2].alpha, 0.1);
  EXPECT_EQ(tf.opacity[3].alpha, 0.3);
  EXPECT_EQ(tf.color[0].value, -1.0);
  EXPECT_NO_THROW(tf.validate());
}

// Expects validate() to throw a message containing `needle`.
void expectInvalid(const TransferFunction& tf, const std::string& needle) {
  try {
    tf.validate();
    ADD_FAILURE() << "no error, expected one about " << needle;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(TransferFunction, ValidateRejectsBadNumbers) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  TransferFunction tf = ramp();
  tf.opacity[1].alpha = 1.5;
  expectInvalid(tf, "opacity point 1: alpha 1.5 is outside [0, 1]");
  tf = ramp();
  tf.opacity[0].alpha = -0.1;
  expectInvalid(tf, "outside [0, 1]");
  tf = ramp();
  tf.opacity[2].alpha = nan;
  expectInvalid(tf, "not finite");
  tf = ramp();
  tf.opacity[2].value = inf;
  expectInvalid(tf, "not finite");
  tf = ramp();
  tf.color[1].value = nan;
  expectInvalid(tf, "color point 1");
  tf = ramp();
  tf.color[0].rgb.g = 1.01;
  expectInvalid(tf, "color point 0: component 1.01 is outside [0, 1]");
  tf = ramp();
  tf.color[0].rgb.b = nan;
  expectInvalid(tf, "color point 0");
  tf = ramp();
  tf.opacityUnitDistance = 0.0;
  expectInvalid(tf, "unit distance");
  tf.opacityUnitDistance = -1.0;
  expectInvalid(tf, "unit distance");
  tf.opacityUnitDistance = inf;
  expectInvalid(tf, "unit distance");
  EXPECT_NO_THROW(ramp().validate());
}

// A 32³ uint8 volume: noisy background around 20, a 12³ block of 200 +- noise in the middle.
Volume bimodalVolume() {
  const int n = 32;
  std::vector<uint8_t> bytes(n * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const bool inside = i >= 10 && i < 22 && j >= 10 && j < 22 && k >= 10 && k < 22;
        const int noise = (i * 7 + j * 13 + k * 29) % 5 - 2;
        bytes[i + n * (j + n * k)] = uint8_t((inside ? 200 : 20) + noise);
      }
  return Volume({n, n, n}, {0.5, 1.0, 2.0}, glm::dvec3(0.0), ScalarType::UInt8, bytes);
}

TEST(DefaultTransferFunction, HidesBackgroundShowsForeground) {
  const Volume volume = bimodalVolume();
  const TransferFunction tf = defaultTransferFunction(volume);
  EXPECT_NO_THROW(tf.validate());
  EXPECT_DOUBLE_EQ(tf.opacityUnitDistance, 0.5);
  for (double v = 18.0; v <= 22.0; v += 1.0) EXPECT_EQ(tf.alphaAt(v), 0.0) << v;
  for (double v = 198.0; v <= 202.0; v += 1.0) EXPECT_GT(tf.alphaAt(v), 0.0) << v;
  EXPECT_FALSE(tf.allTransparent(volume.minValue(), volume.maxValue()));
}

// A volume cropped to its object (as NiBabel's anatomical.nii): no background, a material peak
// at 200 (40% of the voxels) above a spread of lower values (55%, 40 to 188) and a few bright
// ones. The histogram's mode is that peak, with most voxels below it.
TEST(DefaultTransferFunction, AVolumeWithoutBackgroundShowsItsMainMaterial) {
  const int n = 32;
  std::vector<uint8_t> bytes(n * n * n);
  for (int v = 0; v < n * n * n; ++v) {
    const int r = (v * 37) % 100;
    bytes[v] = uint8_t(r < 40 ? 200 + r % 3 : r < 95 ? 40 + (r - 40) * 27 / 10 : 250);
  }
  const Volume volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, bytes);
  const TransferFunction tf = defaultTransferFunction(volume);
  EXPECT_NO_THROW(tf.validate());
  // The peak at 200 is not taken for a background: it and the tail below show, the lowest
  // value only stays clear.
  for (double v : {100.0, 150.0, 199.0, 200.0, 202.0, 250.0}) EXPECT_GT(tf.alphaAt(v), 0.0) << v;
  EXPECT_EQ(tf.alphaAt(40.0), 0.0);
  EXPECT_LT(tf.alphaAt(150.0), tf.alphaAt(250.0));
}

// Masks and labels: the background clear, every label opaque from a quarter of the way to it
// (a structure one voxel thin reconstructs to about a third of its value), each its own colour.
TEST(DefaultTransferFunction, MasksAndLabelsShowEveryLabelFromAQuarterOfTheWay) {
  const int n = 16;
  std::vector<uint8_t> mask(n * n * n, 0), labels(n * n * n, 0);
  for (int v = 0; v < n * n * n; v += 97) mask[v] = 255;
  for (int v = 0; v < n * n * n; v += 31) labels[v] = uint8_t(1 + v % 3);
  const TransferFunction binary = defaultTransferFunction(
      Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, mask));
  EXPECT_NO_THROW(binary.validate());
  EXPECT_EQ(binary.alphaAt(0.0), 0.0);
  // The background's table bin stays clear, so its voxels are no splats.
  EXPECT_EQ(binary.alphaAt(2.0 * 255.0 / Volume::histogramBins()), 0.0);
  EXPECT_GT(binary.alphaAt(0.3 * 255.0), 0.5);
  EXPECT_GT(binary.alphaAt(255.0), 0.5);
  const TransferFunction tf = defaultTransferFunction(
      Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, labels));
  EXPECT_EQ(tf.alphaAt(0.0), 0.0);
  for (double v : {0.3, 1.0, 2.0, 3.0}) EXPECT_GT(tf.alphaAt(v), 0.5) << v;
  EXPECT_NE(tf.colorAt(1.0), tf.colorAt(2.0));
  EXPECT_NE(tf.colorAt(2.0), tf.colorAt(3.0));
}

TEST(DefaultTransferFunction, ConstantAndEmptyVolumesGiveValidFunctions) {
  const Volume constant({4, 4, 4}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8,
                        std::vector<uint8_t>(64, 7));
  EXPECT_NO_THROW(defaultTransferFunction(constant).validate());
  EXPECT_NO_THROW(defaultTransferFunction(Volume()).validate());
}

TEST(DefaultTransferFunction, EngineAirIsClearMetalIsOpaque) {
  const std::string path = std::string(EWA_SHARED_DATA) + "/engine/engine.raw";
  std::ifstream in(path, std::ios::binary);
  if (!in) GTEST_SKIP() << "shared data not found: " << path;
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_EQ(bytes.size(), 256u * 256u * 128u);
  const Volume engine({256, 256, 128}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, bytes);
  const TransferFunction tf = defaultTransferFunction(engine);
  EXPECT_EQ(tf.alphaAt(0.0), 0.0);
  EXPECT_EQ(tf.alphaAt(8.0), 0.0);
  EXPECT_GT(tf.alphaAt(140.0), 0.0);  // the engine block
  EXPECT_GT(tf.alphaAt(250.0), 0.3);  // dense parts
  EXPECT_LT(tf.alphaAt(140.0), tf.alphaAt(250.0));
}

}  // namespace
}  // namespace ewa
