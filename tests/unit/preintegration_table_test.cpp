// Pre-integration table entries against fine numerical integration; opacity/colour correction.
#include "core/preintegration_table.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/opacity_correction.h"
#include "transfer_function_samples.h"

namespace ewa {
namespace {

// A smooth ramp with a colour change, alpha per unit distance 1.
TransferFunction smoothTf() {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {40.0, 0.05}, {200.0, 0.6}, {255.0, 0.9}};
  tf.color = {{0.0, {0.2, 0.3, 1.0}}, {128.0, {1.0, 0.5, 0.1}}, {255.0, {1.0, 1.0, 1.0}}};
  tf.opacityUnitDistance = 1.0;
  return tf;
}

constexpr int kReferenceSteps = 8000;

// Largest difference of any channel between the table and the reference over index pairs.
double maxEntryError(const TransferFunction& tf, double distance, const std::vector<int>& indices) {
  const PreintegrationTable table = PreintegrationTable::build(tf, 0.0, 255.0, 256, distance);
  double worst = 0.0;
  for (int f : indices)
    for (int b : indices) {
      const glm::dvec4 exact = integrateSegment(tf, f, b, distance, kReferenceSteps);
      const glm::vec4 e = table.at(f, b);
      for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(double(e[c]) - exact[c]));
    }
  return worst;
}

std::vector<int> everyNth(int n) {
  std::vector<int> v;
  for (int i = 0; i < 256; i += n) v.push_back(i);
  v.push_back(255);
  return v;
}

TEST(PreintegrationTable, ReferenceIntegrationHasConverged) {
  // The reference itself: doubling its steps changes no entry by more than 1e-5.
  for (const TransferFunction& tf : {smoothTf(), test::thinPeakTf()})
    for (double sf : {0.0, 98.5, 150.0})
      for (double sb : {101.5, 30.0, 255.0}) {
        const glm::dvec4 a = integrateSegment(tf, sf, sb, 1.0, kReferenceSteps);
        const glm::dvec4 b = integrateSegment(tf, sf, sb, 1.0, 4 * kReferenceSteps);
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[c], b[c], 1e-5);
      }
}

TEST(PreintegrationTable, EntriesMatchNumericalIntegrationWithin1e3) {
  EXPECT_LT(maxEntryError(smoothTf(), 1.0, everyNth(17)), 1e-3);
  EXPECT_LT(maxEntryError(smoothTf(), 3.0, everyNth(17)), 1e-3);
  // Around the peak, where the integrand changes fastest.
  const std::vector<int> nearPeak = {0, 1, 60, 97, 98, 99, 100, 101, 102, 103, 150, 254, 255};
  EXPECT_LT(maxEntryError(test::thinPeakTf(), 1.0, nearPeak), 1e-3);
  EXPECT_LT(maxEntryError(test::thinPeakTf(), 4.0, nearPeak), 1e-3);
}

TEST(PreintegrationTable, ThinPeakIsCaughtBetweenDistantValues) {
  // A segment from 0 to 255 crosses the peak: nearly opaque, red, although neither end is.
  const PreintegrationTable t =
      PreintegrationTable::build(test::thinPeakTf(), 0.0, 255.0, 256, 1.0);
  EXPECT_EQ(t.at(0, 0).a, 0.0f);
  EXPECT_EQ(t.at(255, 255).a, 0.0f);
  const glm::dvec4 exact = integrateSegment(test::thinPeakTf(), 0.0, 255.0, 1.0, kReferenceSteps);
  EXPECT_GT(exact.a, 0.005);
  EXPECT_NEAR(t.at(0, 255).a, exact.a, 1e-4);
  EXPECT_NEAR(t.at(255, 0).r, exact.r, 1e-4);
  EXPECT_GT(t.at(0, 255).r, 5.0 * t.at(0, 255).b);
}

TEST(PreintegrationTable, DiagonalIsTheConstantScalarClosedForm) {
  const TransferFunction tf = smoothTf();
  const PreintegrationTable t = PreintegrationTable::build(tf, 0.0, 255.0, 256, 1.5);
  for (int i : {0, 37, 128, 255}) {
    const double alpha = 1.0 - std::exp(-tf.extinctionAt(i) * 1.5);
    EXPECT_NEAR(t.at(i, i).a, alpha, 1e-6);
    EXPECT_NEAR(t.at(i, i).g, tf.colorAt(i).g * alpha, 1e-6);
  }
}

TEST(PreintegrationTable, BlocksGiveEverySegmentItsOwnComposite) {
  // build() composites a diagonal's segments from blocks of sub-bins; buildBySegments()
  // composites each segment alone. Only rounding may differ, also where the segments are
  // opaque (transmittance underflows) and over a single interval.
  TransferFunction opaque = smoothTf();
  opaque.opacityUnitDistance = 1e-3;
  for (const TransferFunction& tf : {smoothTf(), test::thinPeakTf(), opaque})
    for (int size : {2, 3, 17, 256})
      for (int substeps : {1, 3, 4}) {
        const auto fast = PreintegrationTable::build(tf, 0.0, 255.0, size, 2.5, substeps);
        const auto slow = PreintegrationTable::buildBySegments(tf, 0.0, 255.0, size, 2.5, substeps);
        double worst = 0.0;
        for (size_t i = 0; i < fast.entries().size(); ++i)
          for (int c = 0; c < 4; ++c)
            worst = std::max(worst, double(std::abs(fast.entries()[i][c] - slow.entries()[i][c])));
        EXPECT_LT(worst, 1e-6) << "size " << size << ", substeps " << substeps;
      }
}

TEST(PreintegrationTable, RejectsBadArguments) {
  EXPECT_THROW(PreintegrationTable::build(smoothTf(), 0, 1, 1, 1.0), std::invalid_argument);
  EXPECT_THROW(PreintegrationTable::build(smoothTf(), 0, 1, 8, 0.0), std::invalid_argument);
  EXPECT_THROW(PreintegrationTable::build(smoothTf(), 0, NAN, 8, 1.0), std::invalid_argument);
}

TEST(OpacityCorrection, OpacityFollowsTheLayerLength) {
  for (double alpha : {0.0, 1e-9, 0.1, 0.5, 0.99})
    for (double ratio : {0.5, 1.0, 1.7, 3.0}) {
      const double tau = -std::log1p(-alpha);
      EXPECT_NEAR(correctOpacity(alpha, ratio), 1.0 - std::exp(-tau * ratio), 1e-12);
    }
  EXPECT_EQ(correctOpacity(0.3, 1.0), 0.3);
  EXPECT_EQ(correctOpacity(1.0, 0.5), 1.0);
}

TEST(OpacityCorrection, ColourMatchesTheConstantScalarIntegral) {
  // c = colour * (1 - exp(-tau d)); corrected for d' it must equal the integral over d'.
  TransferFunction tf;
  tf.opacity = {{0.0, 0.4}};
  tf.color = {{0.0, {0.8, 0.4, 0.2}}};
  const glm::dvec4 base = integrateSegment(tf, 0.0, 0.0, 1.0, 1000);
  for (double ratio : {0.5, 1.0, 1.732}) {
    const glm::vec4 corrected = correctPremultiplied(glm::vec4(base), ratio);
    const glm::dvec4 direct = integrateSegment(tf, 0.0, 0.0, ratio, 1000);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(corrected[c], direct[c], 1e-6);
  }
  // Sweeney and Mueller's d'/d = 1/2: the factor is 1 / (1 + sqrt(1 - alpha)).
  const glm::vec4 half = correctPremultiplied(glm::vec4(0.3f, 0.2f, 0.1f, 0.6f), 0.5);
  EXPECT_NEAR(half.r / 0.3, 1.0 / (1.0 + std::sqrt(0.4)), 1e-6);
  // Vanishing opacity: emission grows with the length.
  EXPECT_NEAR(correctPremultiplied(glm::vec4(1e-9f, 0, 0, 0), 2.0).r, 2e-9, 1e-15);
}

TEST(OpacityCorrection, TableIsCorrectedEntryByEntry) {
  std::vector<glm::vec4> table = {glm::vec4(0.1f, 0.2f, 0.3f, 0.5f), glm::vec4(0.0f)};
  correctTable(table, 2.0);
  EXPECT_NEAR(table[0].a, 0.75, 1e-6);
  EXPECT_NEAR(table[0].b, 0.3 * 1.5, 1e-6);
  EXPECT_EQ(table[1], glm::vec4(0.0f));
}

}  // namespace
}  // namespace ewa
