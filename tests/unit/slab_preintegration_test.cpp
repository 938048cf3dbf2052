// Pre-integration between slabs: texels from the shared table, their lookup for any length.
#include "core/slab_preintegration.h"

#include <gtest/gtest.h>

#include <cmath>

#include "transfer_function_samples.h"

namespace ewa {
namespace {

TransferFunction rampTf() {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {255.0, 0.9}};
  tf.color = {{0.0, {0.2, 0.3, 1.0}}, {255.0, {1.0, 0.5, 0.1}}};
  tf.opacityUnitDistance = 1.0;
  return tf;
}

constexpr int kSize = 256;

double normalized(double s) {
  return s / 255.0;
}

// Opacity comes from the float extinction prefix over at least one of its 4096 samples: a
// constant segment reads the extinction averaged over that sample's width (one-sided at the
// range's ends), to 1e-3 in opacity.
TEST(SlabPreintegration, ConstantSegmentsFollowTheTransferFunctionAtEveryLength) {
  const TransferFunction tf = rampTf();
  const PreintegrationTable table = PreintegrationTable::build(tf, 0.0, 255.0, kSize, 2.0);
  const std::vector<glm::vec4> texels = slabPairTexels(table, tf);
  const std::vector<float> prefix = extinctionPrefix(tf, 0.0, 255.0, kExtinctionPrefixSize);
  for (int i : {0, 17, 128, 254})
    for (double length : {0.05, 0.7, 2.0, 9.0}) {
      const glm::dvec4 c =
          classifySlabPair(texels, kSize, prefix, normalized(i), normalized(i), length);
      const double alpha = -std::expm1(-tf.extinctionAt(i) * length);
      EXPECT_NEAR(c.a, alpha, 1.5e-3) << i << " " << length;
      EXPECT_NEAR(c.r, tf.colorAt(i).r * alpha, 1.5e-3) << i << " " << length;
      EXPECT_NEAR(c.b, tf.colorAt(i).b * alpha, 1.5e-3) << i << " " << length;
      EXPECT_NEAR(c.r / c.a, tf.colorAt(i).r, 1e-5) << i << " " << length;
    }
}

TEST(SlabPreintegration, AtTheTableDistanceTheLookupIsTheTableEntry) {
  const TransferFunction tf = rampTf();
  const PreintegrationTable table = PreintegrationTable::build(tf, 0.0, 255.0, kSize, 1.5);
  const std::vector<glm::vec4> texels = slabPairTexels(table, tf);
  const std::vector<float> prefix = extinctionPrefix(tf, 0.0, 255.0, kExtinctionPrefixSize);
  for (int f : {0, 40, 200})
    for (int b : {3, 90, 255}) {
      const glm::dvec4 c =
          classifySlabPair(texels, kSize, prefix, normalized(f), normalized(b), 1.5);
      for (int k = 0; k < 4; ++k) EXPECT_NEAR(c[k], table.at(f, b)[k], 2e-6) << f << " " << b;
    }
}

TEST(SlabPreintegration, AThinPeakBetweenTwoValuesIsCaughtAtAnyLength) {
  // Both ends are transparent; the segment crosses the peak. Standard classification of
  // either end (or their mean, 100.5 here, just off the peak's top) misses or halves it.
  const TransferFunction tf = test::thinPeakTf();
  const PreintegrationTable table = PreintegrationTable::build(tf, 0.0, 255.0, kSize, 2.0);
  const std::vector<glm::vec4> texels = slabPairTexels(table, tf);
  const std::vector<float> prefix = extinctionPrefix(tf, 0.0, 255.0, kExtinctionPrefixSize);
  for (auto [f, b] : {std::pair{80.0, 121.0}, {121.0, 80.0}, {96.0, 104.0}})
    for (double length : {0.5, 2.0, 6.0}) {
      const glm::dvec4 c =
          classifySlabPair(texels, kSize, prefix, normalized(f), normalized(b), length);
      const glm::dvec4 exact = integrateSegment(tf, f, b, length, 20000);
      EXPECT_GT(exact.a, 0.02);
      EXPECT_NEAR(c.a, exact.a, 0.03 * exact.a) << f << " " << b << " " << length;
      // Colour per unit opacity: the peak's colour.
      EXPECT_NEAR(c.r / c.a, exact.r / exact.a, 0.02);
      EXPECT_NEAR(c.g / c.a, exact.g / exact.a, 0.02);
      EXPECT_EQ(classifySlabPair(texels, kSize, prefix, normalized(f), normalized(f), length).a,
                0.0);
      EXPECT_EQ(classifySlabPair(texels, kSize, prefix, normalized(b), normalized(b), length).a,
                0.0);
    }
}

// An MR volume's case: a wide uint16 range (1026 to 5119, 16 values a table entry) and a
// transfer function that rises within one entry. The pair table's bilinear extinction
// smeared the step (a brain surface came out 7% darker than a ray caster's); the prefix keeps
// it to within one of its 4096 samples (1 value).
TEST(SlabPreintegration, ASharpStepInAWideRangeKeepsItsOpacity) {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {1100.0, 0.0}, {1110.0, 0.9}, {5119.0, 0.9}};
  tf.color = {{0.0, {1.0, 1.0, 1.0}}, {5119.0, {1.0, 1.0, 1.0}}};
  tf.opacityUnitDistance = 1.0;
  const double lo = 1026.0, hi = 5119.0;
  const PreintegrationTable table = PreintegrationTable::build(tf, lo, hi, kSize, 1.0);
  const std::vector<glm::vec4> texels = slabPairTexels(table, tf);
  const std::vector<float> prefix = extinctionPrefix(tf, lo, hi, kExtinctionPrefixSize);
  const auto x = [&](double v) { return (v - lo) / (hi - lo); };
  for (double v : {1112.0, 1115.0, 1120.0, 1500.0}) {
    const glm::dvec4 c = classifySlabPair(texels, kSize, prefix, x(v), x(v), 1.0);
    EXPECT_NEAR(c.a, 0.9, 1e-3) << v;
    EXPECT_NEAR(c.g / c.a, 1.0, 1e-5) << v;  // white, not darkened by transparent entries
  }
  // Below the step: transparent.
  EXPECT_LT(classifySlabPair(texels, kSize, prefix, x(1098.0), x(1098.0), 1.0).a, 1e-3);
  // A segment across the step: the part above it, (1300 - 1110) / (1300 - 1050) of its length.
  const double tau = -std::log(0.1) * (1300.0 - 1110.0) / (1300.0 - 1050.0);
  EXPECT_NEAR(classifySlabPair(texels, kSize, prefix, x(1050.0), x(1300.0), 1.0).a,
              -std::expm1(-tau), 0.01);
  // What the table's own bilinear extinction gave at 1112 (between entries 5 and 6, 1106 and
  // 1122): about 0.74 instead of 0.9.
  const double p = x(1112.0) * (kSize - 1);
  const int i = int(p);
  const double t = p - i;
  const auto tauAt = [&](int f, int b) { return double(texels[size_t(f) * kSize + b].a); };
  const double smeared = (1 - t) * ((1 - t) * tauAt(i, i) + t * tauAt(i, i + 1)) +
                         t * ((1 - t) * tauAt(i + 1, i) + t * tauAt(i + 1, i + 1));
  EXPECT_LT(-std::expm1(-smeared), 0.8);
}

TEST(SlabPreintegration, MeanExtinctionStaysFiniteWhereTheEntryIsOpaque) {
  // tau d large enough that 1 - alpha rounds to 0 in float: the texel keeps the extinction.
  TransferFunction tf = rampTf();
  tf.opacityUnitDistance = 0.001;
  const PreintegrationTable table = PreintegrationTable::build(tf, 0.0, 255.0, kSize, 2.0);
  EXPECT_EQ(table.at(250, 255).a, 1.0f);
  const std::vector<glm::vec4> texels = slabPairTexels(table, tf);
  const std::vector<float> prefix = extinctionPrefix(tf, 0.0, 255.0, kExtinctionPrefixSize);
  const double tau = texels[size_t(250) * kSize + 255].a;
  EXPECT_TRUE(std::isfinite(tau));
  EXPECT_NEAR(tau, 0.5 * (tf.extinctionAt(250) + tf.extinctionAt(255)), 1e-3 * tau);
  // A sliver of that segment (a silhouette pixel's share) is far from opaque; the opacity's
  // extinction is capped at kMaxPrefixExtinction (1000 a world unit, here about half the
  // table's), and a hundredth of a unit is opaque.
  const glm::dvec4 c =
      classifySlabPair(texels, kSize, prefix, normalized(250), normalized(255), 1e-5);
  EXPECT_NEAR(c.a, -std::expm1(-1e-5 * kMaxPrefixExtinction), 1e-6);
  EXPECT_LT(c.a, 0.1);
  EXPECT_GT(classifySlabPair(texels, kSize, prefix, normalized(250), normalized(255), 0.01).a,
            0.9999);
}

}  // namespace
}  // namespace ewa
