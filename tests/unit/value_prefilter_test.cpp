// The value prefilter of post-classified splats: v + strength * (6 v - the 6 neighbours),
// clamped to the value range, leaving smooth fields alone and the set of splats unchanged.
#include "core/value_prefilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <vector>

#include "core/splat_attributes.h"

namespace ewa {
namespace {

// An n^3 float32 volume of unit spacing with value f(i, j, k).
Volume field(int n, const std::function<float(int, int, int)>& f) {
  std::vector<float> v(size_t(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) v[size_t(i + n * (j + n * k))] = f(i, j, k);
  std::vector<uint8_t> bytes(v.size() * sizeof(float));
  std::memcpy(bytes.data(), v.data(), bytes.size());
  return Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::Float32, std::move(bytes));
}

// 0.5 everywhere, a spike of 0.6 at (3,3,3), and the range's ends 0 and 1 in two corners, so
// nothing near the spike is clamped.
Volume spike() {
  return field(7, [](int i, int j, int k) {
    if (i == 3 && j == 3 && k == 3) return 0.6f;
    if (i + j + k == 0) return 0.0f;
    if (i + j + k == 18) return 1.0f;
    return 0.5f;
  });
}

TEST(ValuePrefilter, SpikeRisesByItsLaplacianAndItsNeighboursFall) {
  const Volume v = spike();
  const double b = 0.05;
  // The spike: 0.6 + b * 6 * 0.1; a face neighbour: 0.5 + b * (5 * 0.5 + 0.5 - (5 * 0.5 + 0.6)).
  EXPECT_NEAR(prefilteredValue(v, 3, 3, 3, b), 0.6 + b * 0.6, 1e-6);
  EXPECT_NEAR(prefilteredValue(v, 4, 3, 3, b), 0.5 - b * 0.1, 1e-6);
  EXPECT_NEAR(prefilteredValue(v, 3, 2, 3, b), 0.5 - b * 0.1, 1e-6);
  EXPECT_NEAR(prefilteredValue(v, 3, 3, 4, b), 0.5 - b * 0.1, 1e-6);
  EXPECT_NEAR(prefilteredValue(v, 4, 4, 3, b), 0.5, 1e-6);  // diagonal: not a face neighbour
  EXPECT_NEAR(prefilteredValue(v, 3, 3, 3, 0.2), 0.6 + 0.2 * 0.6, 1e-6);  // linear in strength
  EXPECT_EQ(prefilteredValue(v, 3, 3, 3, 0.0), v.value(3, 3, 3));
}

TEST(ValuePrefilter, ConstantAndLinearFieldsAreUnchanged) {
  const Volume ramp = field(6, [](int i, int j, int k) { return float(i + 2 * j + 3 * k); });
  for (int k = 1; k < 5; ++k)
    for (int j = 1; j < 5; ++j)
      for (int i = 1; i < 5; ++i)
        EXPECT_NEAR(prefilteredValue(ramp, i, j, k, 0.2), ramp.value(i, j, k), 1e-9);
  // A constant field, border included: voxels beyond the border count as the voxel itself.
  const Volume flat = field(4, [](int i, int j, int) { return i + j == 0 ? 0.0f : 0.3f; });
  EXPECT_NEAR(prefilteredValue(flat, 3, 3, 3, 0.2), 0.3, 1e-6);
  EXPECT_NEAR(prefilteredValue(flat, 3, 0, 2, 0.2), 0.3, 1e-6);
}

TEST(ValuePrefilter, ClampsToTheRangeAndSkipsNonFiniteNeighbours) {
  Volume v = field(5, [](int i, int j, int k) {
    if (i == 2 && j == 2 && k == 2) return 1.0f;  // the maximum, above all its neighbours
    if (i == 1 && j == 2 && k == 2) return NAN;
    return i + j + k == 0 ? 0.0f : 0.2f;
  });
  EXPECT_EQ(prefilteredValue(v, 2, 2, 2, 0.25), 1.0);  // 1 + 0.25 * 4 * 0.8, clamped
  EXPECT_NEAR(prefilteredValue(v, 3, 2, 2, 0.25), 0.2 - 0.25 * 0.8, 1e-6);
  EXPECT_TRUE(std::isnan(prefilteredValue(v, 1, 2, 2, 0.25)));  // NaN stays NaN
  // Its neighbour beside the NaN sees 0.2 on the far side and itself in the NaN's place.
  EXPECT_NEAR(prefilteredValue(v, 0, 2, 2, 0.25), 0.2, 1e-6);
  EXPECT_NEAR(prefilteredValue(v, 1, 1, 1, 0.25), 0.2, 1e-6);  // its neighbours are all 0.2
}

TEST(ValuePrefilter, PostSplatsCarryPrefilteredValuesOfTheSameVoxels) {
  const Volume v = spike();
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {0.55, 0.0}, {0.6, 1.0}, {1.0, 1.0}};
  Classification plain = postClassification(), sharp = postClassification();
  plain.prefilter = 0.0;
  sharp.prefilter = 0.1;
  const ClassifiedSplats a = classifySplats(v, tf, plain), b = classifySplats(v, tf, sharp);
  ASSERT_EQ(a.splats.size(), b.splats.size());
  ASSERT_GT(a.splats.size(), 7u);  // the spike, its margin, the far corner
  for (size_t n = 0; n < a.splats.size(); ++n) {
    const PackedSplat& p = a.splats.splats()[n];
    const PackedSplat& q = b.splats.splats()[n];
    ASSERT_EQ(p.ij, q.ij);
    ASSERT_EQ(SplatSet::k(p), SplatSet::k(q));
    const auto i = SplatSet::i(p), j = SplatSet::j(p), k = SplatSet::k(p);
    EXPECT_NEAR(SplatSet::normalizedValue(p), v.value(i, j, k), 1e-4);
    EXPECT_NEAR(SplatSet::normalizedValue(q), prefilteredValue(v, i, j, k, 0.1), 1e-4);
  }
  // The spike itself carries 0.6 + 0.1 * 6 * 0.1, its face neighbours 0.5 - 0.1 * 0.1.
  int checked = 0;
  for (const PackedSplat& q : b.splats.splats()) {
    const auto i = SplatSet::i(q), j = SplatSet::j(q), k = SplatSet::k(q);
    if (i == 3 && j == 3 && k == 3) {
      EXPECT_NEAR(SplatSet::normalizedValue(q), 0.66, 1e-4);
      ++checked;
    } else if (i == 4 && j == 3 && k == 3) {
      EXPECT_NEAR(SplatSet::normalizedValue(q), 0.49, 1e-4);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2);
  // Pre-classification keeps the data's values whatever the prefilter says.
  Classification pre = sharp;
  pre.mode = ClassificationMode::Pre;
  const ClassifiedSplats c = classifySplats(v, tf, pre);
  for (const PackedSplat& p : c.splats.splats())
    EXPECT_NEAR(SplatSet::normalizedValue(p),
                v.value(SplatSet::i(p), SplatSet::j(p), SplatSet::k(p)), 1e-4);
}

TEST(ValuePrefilter, ChangingItRebuildsPostSplatsOnly) {
  Classification a = postClassification(), b = postClassification();
  EXPECT_EQ(a.prefilter, kDefaultPrefilter);
  b.prefilter = 0.0;
  EXPECT_NE(a, b);
  a.mode = b.mode = ClassificationMode::Pre;
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace ewa
