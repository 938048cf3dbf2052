// Unit tests of the synthetic volumes: analytic values, layouts, spec parsing.
#include "core/synthetic_volume.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ewa {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(SyntheticVolume, MarschnerLobbMatchesTheFormula) {
  const SyntheticVolume s = makeSyntheticVolume("marschner-lobb");
  const Volume& v = s.volume;
  EXPECT_EQ(s.name, "marschner-lobb:41");
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{41, 41, 41}));
  EXPECT_EQ(v.type(), ScalarType::Float32);
  EXPECT_EQ(v.spacing(), glm::dvec3(1.0));
  EXPECT_EQ(v.origin(), glm::dvec3(0.0));
  // Index 20 is coordinate 0, 40 is +1, 0 is -1, 30 is +0.5.
  EXPECT_NEAR(v.value(20, 20, 20), 0.6, 1e-6);  // (1 - 0 + 0.25 * 2) / 2.5
  EXPECT_NEAR(v.value(20, 20, 40), 0.2, 1e-6);  // sin(pi/2) = 1
  EXPECT_NEAR(v.value(20, 20, 0), 1.0, 1e-6);   // sin(-pi/2) = -1
  EXPECT_NEAR(v.value(40, 20, 20), 0.6, 1e-6);  // r = 1: cos(2 pi 6 cos(pi/2)) = 1
  const double r = std::sqrt(2.0), rho = std::cos(12.0 * kPi * std::cos(kPi * r / 2.0));
  EXPECT_NEAR(v.value(0, 0, 20), (1.0 + 0.25 * (1.0 + rho)) / 2.5, 1e-6);
  const double rhoHalf = std::cos(12.0 * kPi * std::cos(kPi * 0.25));
  EXPECT_NEAR(v.value(30, 20, 30), (1.0 - std::sin(kPi * 0.25) + 0.25 * (1.0 + rhoHalf)) / 2.5,
              1e-6);
  EXPECT_GE(v.minValue(), 0.0);
  EXPECT_LE(v.maxValue(), 1.0);
  ASSERT_TRUE(s.transferFunction);
  EXPECT_EQ(s.transferFunction->alphaAt(0.3), 0.0);
  EXPECT_GT(s.transferFunction->alphaAt(0.6), 0.5);
  EXPECT_EQ(makeSyntheticVolume("marschner-lobb:9").volume.dims()[2], 9);
}

TEST(SyntheticVolume, SphereIsASmoothBall) {
  const SyntheticVolume s = makeSyntheticVolume("sphere:32");
  const Volume& v = s.volume;
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{32, 32, 32}));
  EXPECT_EQ(v.type(), ScalarType::UInt8);
  EXPECT_EQ(v.value(16, 16, 16), 255.0);
  EXPECT_EQ(v.value(0, 0, 0), 0.0);
  // Radius 12.8 about 15.5: 14 voxels out along x is outside, 11 is inside, 13 is on the edge.
  EXPECT_EQ(v.value(15 + 14, 15, 15), 0.0);
  EXPECT_EQ(v.value(15 + 11, 15, 15), 255.0);
  EXPECT_GT(v.value(28, 15, 15), 0.0);
  EXPECT_LT(v.value(28, 15, 15), 255.0);
  ASSERT_TRUE(s.transferFunction);
  EXPECT_NO_THROW(s.transferFunction->validate());
  EXPECT_GT(s.transferFunction->alphaAt(255.0), 0.0);
  EXPECT_LT(s.transferFunction->alphaAt(255.0), 1.0);
  EXPECT_EQ(makeSyntheticVolume("sphere").volume.dims()[0], 64);
}

TEST(SyntheticVolume, BoxIsHomogeneous) {
  const SyntheticVolume s = makeSyntheticVolume("box:8");
  EXPECT_EQ(s.volume.minValue(), 255.0);
  EXPECT_EQ(s.volume.maxValue(), 255.0);
  EXPECT_EQ(s.volume.voxelCount(), 512);
}

TEST(SyntheticVolume, CheckerboardAlternatesSquares) {
  const SyntheticVolume s = makeSyntheticVolume("checkerboard");
  const Volume& v = s.volume;
  EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{400, 400, 1}));
  EXPECT_EQ(v.spacing(), glm::dvec3(1.0));
  for (int j = 0; j < 400; j += 7)
    for (int i = 0; i < 400; i += 3) {
      const int expected = ((i / 10 + j / 10) % 2 == 0) ? 1 : 2;
      ASSERT_EQ(v.value(i, j, 0), expected) << i << "," << j;
    }
  // Square edges: 0..9 is one square, 10 starts the next, both ways.
  EXPECT_EQ(v.value(9, 9, 0), 1.0);
  EXPECT_EQ(v.value(10, 9, 0), 2.0);
  EXPECT_EQ(v.value(9, 10, 0), 2.0);
  EXPECT_EQ(v.value(10, 10, 0), 1.0);
  EXPECT_EQ(v.value(399, 399, 0), 1.0);
  ASSERT_TRUE(s.transferFunction);
  const TransferFunction& tf = *s.transferFunction;
  EXPECT_EQ(tf.colorAt(1.0), glm::dvec3(1.0, 0.0, 0.0));
  EXPECT_EQ(tf.colorAt(2.0), glm::dvec3(1.0));
  EXPECT_GE(tf.alphaAt(1.0), 0.95);
  EXPECT_GE(tf.alphaAt(2.0), 0.95);
  EXPECT_EQ(tf.opacityUnitDistance, 1.0);
  EXPECT_EQ(makeSyntheticVolume("checkerboard:40").volume.value(39, 0, 0), 1.0);
  EXPECT_EQ(makeSyntheticVolume("checkerboard:40").volume.value(40, 0, 0), 2.0);
}

TEST(SyntheticVolume, ZebraIsAnisotropicAndSquare) {
  for (int ratio : {1, 2, 4}) {
    const SyntheticVolume s = makeSyntheticVolume("zebra:" + std::to_string(ratio));
    const Volume& v = s.volume;
    EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{256 * ratio, 256, 1}));
    EXPECT_EQ(v.spacing(), glm::dvec3(1.0 / ratio, 1.0, 1.0));
    const glm::dvec3 extent = v.boundsMax() - v.boundsMin();
    EXPECT_NEAR(extent.x, extent.y, 1.0);
    EXPECT_GE(v.minValue(), 0.0);
    EXPECT_LE(v.maxValue(), 1.0);
    EXPECT_LT(v.minValue(), 0.05);  // both stripe colors occur
    EXPECT_GT(v.maxValue(), 0.95);
  }
  const SyntheticVolume s = makeSyntheticVolume("zebra");
  EXPECT_EQ(s.name, "zebra:4");
  EXPECT_EQ(s.volume.dims()[0], 1024);
  ASSERT_TRUE(s.transferFunction);
  EXPECT_EQ(s.transferFunction->colorAt(0.0), glm::dvec3(0.0));
  EXPECT_EQ(s.transferFunction->colorAt(1.0), glm::dvec3(1.0));
  EXPECT_GE(s.transferFunction->alphaAt(0.0), 0.95);
  // Stripes get finer along x: count black/white crossings in each half of row 0.
  auto crossings = [&](int from, int to) {
    int n = 0;
    for (int i = from + 1; i < to; ++i)
      n += (s.volume.value(i - 1, 0, 0) < 0.5) != (s.volume.value(i, 0, 0) < 0.5);
    return n;
  };
  EXPECT_GT(crossings(512, 1024), 2 * crossings(0, 512));
}

TEST(SyntheticVolume, BadSpecsAreRejected) {
  for (const char* spec : {"", "foo", "sphere:1", "sphere:513", "sphere:abc", "sphere:",
                           "sphere:12x", "sphere:-4", "marschner-lobb:0", "zebra:0", "zebra:17",
                           "zebra:2.5", "checkerboard:0", "Sphere", "sphere:99999999999"}) {
    try {
      makeSyntheticVolume(spec);
      ADD_FAILURE() << "no error for '" << spec << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(std::string("--synthetic ") + spec + ": ", 0), 0u)
          << e.what();
    }
  }
  EXPECT_NO_THROW(makeSyntheticVolume("sphere:2"));
  EXPECT_NO_THROW(makeSyntheticVolume("zebra:1"));
}

}  // namespace
}  // namespace ewa
