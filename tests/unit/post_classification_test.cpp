// The voxels post-classified splatting keeps: visible ones, transfer-function crossings between
// neighbours, and a margin as wide as a kernel reaches.
#include "core/post_classification.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/ewa_footprint.h"
#include "core/splat_attributes.h"

namespace ewa {
namespace {

Volume line(const std::vector<uint8_t>& values) {
  return Volume({int64_t(values.size()), 1, 1}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8,
                values);
}

TEST(PostClassification, MarginFollowsTheKernelsReach) {
  // Squared distances in voxel steps: cutoff * width^2, rounded down.
  EXPECT_EQ(postClassificationMarginSquared(4.0, 1.0), 4);
  EXPECT_EQ(postClassificationMarginSquared(4.0, 0.85), 2);  // reach^2 2.89
  EXPECT_EQ(postClassificationMarginSquared(5.0, 0.7), 2);   // reach^2 2.45: 18 neighbours
  EXPECT_EQ(postClassificationMarginSquared(4.0, 0.7), 1);   // reach^2 1.96: the face ones
  EXPECT_EQ(postClassificationMarginSquared(4.0, 0.5), 1);
  EXPECT_EQ(postClassificationMarginSquared(9.0, 1.5), 20);
  EXPECT_EQ(postClassificationMarginSquared(9.0, 1.0), 9);
  EXPECT_EQ(postClassificationMarginSquared(4.0, 0.1), 1);     // never none: neighbours matter
  EXPECT_EQ(postClassificationMarginSquared(64.0, 2.0), 225);  // at most 15^2: the mask's limit
}

// The largest error of the weighted mean Σ w·v / Σ w anywhere a lone visible voxel's kernel
// reaches (its value 1, every other voxel 0) when only the voxels within squared distance
// `marginSquared` of it are splatted, against all of them: kernels of `width` voxel steps,
// windowed at `cutoff` (windowedGaussian).
double worstMeanError(int marginSquared, double cutoff, double width) {
  const double reach2 = cutoff * width * width;
  const int n = int(std::ceil(2.0 * std::sqrt(reach2)));
  auto weight = [&](double d2) { return windowedGaussian(d2 / (width * width), cutoff); };
  double worst = 0.0;
  const double step = 0.125;
  for (double x = 0.0; x * x <= reach2; x += step)  // one octant: the lattice's symmetry
    for (double y = 0.0; x * x + y * y <= reach2; y += step)
      for (double z = 0.0; x * x + y * y + z * z <= reach2; z += step) {
        double all = 0.0, kept = 0.0;
        for (int k = -n; k <= n; ++k)
          for (int j = -n; j <= n; ++j)
            for (int i = -n; i <= n; ++i) {
              const double w = weight((x - i) * (x - i) + (y - j) * (y - j) + (z - k) * (z - k));
              all += w;
              if (i * i + j * j + k * k <= marginSquared) kept += w;
            }
        const double own = weight(x * x + y * y + z * z);
        if (kept > 0.0) worst = std::max(worst, own / kept - own / all);
      }
  return worst;
}

TEST(PostClassification, MarginKeepsTheMeanWhereAVisibleKernelReaches) {
  // At the defaults (width 0.7, cutoff 5) the face neighbours alone left the mean up to 12% of
  // the contrast too near the visible value (thin structures swelled); the voxels within the
  // reach (squared distance 2) leave under 2%. Measured: 0.125, 0.018, 0.006 (3), 0.002 (4);
  // width 1 (squared distance 5) 0.005.
  const int defaults = postClassificationMarginSquared(5.0, 0.7);
  EXPECT_LT(worstMeanError(defaults, 5.0, 0.7), 0.02);
  EXPECT_GT(worstMeanError(1, 5.0, 0.7), 0.1);
  // Wider kernels keep a wider margin, and as little error.
  EXPECT_LT(worstMeanError(postClassificationMarginSquared(5.0, 1.0), 5.0, 1.0), 0.02);
}

TEST(PostClassification, MaskDilatesVisibleVoxelsByTheMargin) {
  const Volume v = line({0, 0, 0, 0, 0, 255, 0, 0, 0, 0, 0});
  const auto visible = [](double x) { return x > 200.0; };
  const std::vector<uint8_t> expected = {0, 0, 0, 1, 1, 1, 1, 1, 0, 0, 0};
  EXPECT_EQ(postClassificationMask(v, visible, 4), expected);  // two steps either side
  const std::vector<uint8_t> near = {0, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0};
  EXPECT_EQ(postClassificationMask(v, visible, 3), near);  // 2^2 = 4 > 3: one step
  const std::vector<uint8_t> none(11, 0);
  EXPECT_EQ(postClassificationMask(
                v, [](double) { return false; }, 4),
            none);
}

// The margin is a ball of the margin's squared radius in voxel steps (a kernel reaches as far in
// every direction), not a cube: checked against the brute-force definition on random seeds.
TEST(PostClassification, MarginIsABallAroundEachVisibleVoxel) {
  const std::array<int64_t, 3> dims = {13, 11, 9};
  std::vector<uint8_t> bytes(size_t(dims[0] * dims[1] * dims[2]), 0);
  uint32_t state = 12345;
  for (uint8_t& b : bytes) {
    state = state * 1664525u + 1013904223u;
    b = (state >> 24) < 3 ? 255 : 0;  // about 1% seeds
  }
  bytes[0] = 255;  // a corner seed: the window must stop at the edges
  const Volume v(dims, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, bytes);
  const auto visible = [](double x) { return x > 200.0; };
  // 36: a window wider than the grid along z; 2, 3 and 5: radii between whole voxels.
  for (int r2 : {1, 2, 3, 4, 5, 9, 36}) {
    const std::vector<uint8_t> mask = postClassificationMask(v, visible, r2);
    size_t kept = 0;
    for (int64_t k = 0; k < dims[2]; ++k)
      for (int64_t j = 0; j < dims[1]; ++j)
        for (int64_t i = 0; i < dims[0]; ++i) {
          bool near = false;
          for (int64_t c = 0; c < dims[2] && !near; ++c)
            for (int64_t b = 0; b < dims[1] && !near; ++b)
              for (int64_t a = 0; a < dims[0] && !near; ++a)
                near = bytes[size_t(v.index(a, b, c))] &&
                       (a - i) * (a - i) + (b - j) * (b - j) + (c - k) * (c - k) <= r2;
          ASSERT_EQ(mask[size_t(v.index(i, j, k))], near ? 1 : 0)
              << "squared margin " << r2 << " at " << i << "," << j << "," << k;
          kept += near;
        }
    EXPECT_GT(kept, 0u);
  }
  // One seed, radius 2: 1 + 6 + 12 + 8 (the (1,1,1) diagonals, 1.73 away) + 6 (two steps along
  // an axis) = 33 voxels; a cube would keep 125. Squared radius 2 (the default kernel's
  // reach): 1 + 6 + 12 = 19.
  std::vector<uint8_t> one(size_t(dims[0] * dims[1] * dims[2]), 0);
  one[size_t(v.index(6, 5, 4))] = 255;
  const Volume single(dims, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, one);
  const auto count = [&](int r2) {
    size_t n = 0;
    for (uint8_t m : postClassificationMask(single, visible, r2)) n += m;
    return n;
  };
  EXPECT_EQ(count(4), 33u);
  EXPECT_EQ(count(2), 19u);
}

TEST(PostClassification, MaskFindsPeaksBetweenNeighbouringValues) {
  // Neither 20 nor 240 is visible, but the value passes 128 between them.
  const Volume v = line({20, 20, 20, 240, 240, 240, 240});
  const auto peak = [](double x) { return x > 120.0 && x < 136.0; };
  const std::vector<uint8_t> expected = {0, 1, 1, 1, 1, 0, 0};
  EXPECT_EQ(postClassificationMask(v, peak, 1), expected);
}

TEST(PostClassification, ClassifiedSplatsKeepTheMarginAndNoSurfaces) {
  std::vector<uint8_t> bytes(9 * 9 * 9, 0);
  bytes[4 + 9 * (4 + 9 * 4)] = 255;
  const Volume v({9, 9, 9}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, bytes);
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {100.0, 0.0}, {200.0, 1.0}, {255.0, 1.0}};
  Classification c;
  c.surface = SurfaceCriterion::Value;
  c.threshold = 128.0;
  EXPECT_EQ(classifySplats(v, tf, c).splats.size(), 1u);
  c.mode = ClassificationMode::Post;
  c.postMarginSquared = 1;
  const ClassifiedSplats post = classifySplats(v, tf, c);
  EXPECT_EQ(post.splats.size(), 7u);  // the voxel and its six face neighbours: a ball
  EXPECT_EQ(post.surfaceCount, 0u);
  std::string name = classificationModeName(ClassificationMode::Post);
  ClassificationMode parsed = ClassificationMode::Pre;
  EXPECT_TRUE(parseClassificationMode(name, &parsed));
  EXPECT_EQ(parsed, ClassificationMode::Post);
  EXPECT_FALSE(parseClassificationMode("mid", &parsed));
}

}  // namespace
}  // namespace ewa
