// Classification on several threads: chunks in order, and the same splats for any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/parallel_chunks.h"
#include "core/post_classification.h"
#include "core/splat_attributes.h"
#include "core/splat_set.h"

namespace ewa {
namespace {

TEST(ParallelChunks, CoverTheRangeInOrderAndRethrowTheFirstError) {
  std::vector<std::pair<size_t, size_t>> seen(8, {0, 0});
  EXPECT_EQ(parallelChunks(10, 1, 3,
                           [&](size_t first, size_t last, size_t c) {
                             seen[c] = {first, last};
                           }),
            3u);
  EXPECT_EQ(seen[0], std::make_pair(size_t(0), size_t(3)));
  EXPECT_EQ(seen[1], std::make_pair(size_t(3), size_t(6)));
  EXPECT_EQ(seen[2], std::make_pair(size_t(6), size_t(10)));
  EXPECT_EQ(chunkCount(10, 4, 3), 2u);  // at least 4 items a chunk
  EXPECT_EQ(chunkCount(3, 4, 3), 1u);   // fewer than a chunk's worth: one, on the caller
  EXPECT_EQ(chunkCount(0, 1, 3), 0u);
  bool called = false;
  EXPECT_EQ(parallelChunks(0, 1, 3, [&](size_t, size_t, size_t) { called = true; }), 0u);
  EXPECT_FALSE(called);
  EXPECT_EQ(workerThreads(5), 5u);
  EXPECT_GE(workerThreads(0), 1u);
  EXPECT_LE(workerThreads(0), 16u);
  try {
    parallelChunks(30, 1, 3, [](size_t, size_t, size_t c) {
      if (c > 0) throw std::runtime_error("chunk " + std::to_string(c));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "chunk 1");
  }
}

TEST(ParallelChunks, ResultsComeBackOnePerChunkInChunkOrder) {
  // Each chunk returns its range: joined in order they tile [0, count) as one loop would.
  const auto ranges =
      parallelChunkResults<std::vector<size_t>>(100, 7, 4, [](size_t first, size_t last) {
        std::vector<size_t> items;
        for (size_t i = first; i < last; ++i) items.push_back(i);
        return items;
      });
  ASSERT_EQ(ranges.size(), chunkCount(100, 7, 4));
  ASSERT_EQ(ranges.size(), 4u);
  std::vector<size_t> joined;
  for (const auto& r : ranges) {
    EXPECT_FALSE(r.empty());
    joined.insert(joined.end(), r.begin(), r.end());
  }
  ASSERT_EQ(joined.size(), 100u);
  for (size_t i = 0; i < joined.size(); ++i) EXPECT_EQ(joined[i], i);
  EXPECT_TRUE(parallelChunkResults<int>(0, 1, 3, [](size_t, size_t) { return 1; }).empty());
  // An error in a chunk still reaches the caller.
  EXPECT_THROW(parallelChunkResults<int>(30, 1, 3,
                                         [](size_t first, size_t) -> int {
                                           if (first > 0) throw std::runtime_error("late chunk");
                                           return 0;
                                         }),
               std::runtime_error);
}

// A float field with smooth lobes, noise, NaNs and a thin transfer-function peak between voxel
// values: every part of the mask (seeds, crossings, margin) and of classification is exercised,
// with chunk boundaries inside each pass at 3 and 7 threads (96 x 96 rows, 40 slices).
Volume awkwardVolume() {
  const std::array<int64_t, 3> d = {96, 96, 40};
  std::vector<float> values(size_t(d[0] * d[1] * d[2]));
  uint32_t state = 777;
  for (int64_t k = 0; k < d[2]; ++k)
    for (int64_t j = 0; j < d[1]; ++j)
      for (int64_t i = 0; i < d[0]; ++i) {
        state = state * 1664525u + 1013904223u;
        const double noise = double(state >> 8) / double(1u << 24) - 0.5;
        double v = 100.0 * std::sin(0.21 * double(i)) * std::cos(0.17 * double(j)) +
                   60.0 * std::sin(0.3 * double(k)) + 8.0 * noise;
        if ((state >> 4) % 997 == 0) v = std::numeric_limits<double>::quiet_NaN();
        values[size_t(i + d[0] * (j + d[1] * k))] = float(v);
      }
  std::vector<uint8_t> bytes(values.size() * sizeof(float));
  std::memcpy(bytes.data(), values.data(), bytes.size());
  return Volume(d, glm::dvec3(1.0, 1.0, 1.3), glm::dvec3(0.0), ScalarType::Float32, bytes);
}

TransferFunction peakAndBand() {
  TransferFunction tf;
  // A thin peak at 20 (crossings between neighbours) and a band above 110.
  tf.opacity = {{-200.0, 0.0}, {19.9, 0.0},  {20.0, 0.8}, {20.1, 0.0},
                {110.0, 0.0},  {130.0, 0.6}, {200.0, 0.6}};
  return tf;
}

void expectSameSplats(const ClassifiedSplats& a, const ClassifiedSplats& b, unsigned threads) {
  ASSERT_EQ(a.splats.size(), b.splats.size()) << threads << " threads";
  EXPECT_EQ(a.surfaceCount, b.surfaceCount) << threads << " threads";
  for (size_t n = 0; n < a.splats.size(); ++n) {
    const PackedSplat &p = a.splats.splats()[n], &q = b.splats.splats()[n];
    ASSERT_TRUE(p.ij == q.ij && p.kValue == q.kValue) << "splat " << n << ", " << threads;
    ASSERT_EQ(std::memcmp(&a.attributes[n], &b.attributes[n], sizeof(PackedAttributes)), 0)
        << "attributes of splat " << n << ", " << threads << " threads";
  }
}

TEST(ParallelClassification, SameMaskAndSplatsForAnyThreadCount) {
  const Volume v = awkwardVolume();
  const TransferFunction tf = peakAndBand();
  const auto visible = [&tf](double x) { return tf.alphaAt(x) > 0.0; };
  const std::vector<uint8_t> one = postClassificationMask(v, visible, 4, 1);
  size_t kept = 0;
  for (uint8_t m : one) kept += m;
  EXPECT_GT(kept, one.size() / 10);  // neither empty nor everything
  EXPECT_LT(kept, one.size() * 9 / 10);
  for (unsigned threads : {2u, 3u, 7u})
    EXPECT_EQ(postClassificationMask(v, visible, 4, threads), one);

  Classification post = postClassification();
  post.postMarginSquared = 4;
  Classification surfaces;  // pre-classified with surface splats: the other predicate
  surfaces.surface = SurfaceCriterion::Value;
  surfaces.threshold = 120.0;
  for (const Classification& c : {post, surfaces}) {
    const ClassifiedSplats single = classifySplats(v, tf, c, SIZE_MAX, 1);
    EXPECT_GT(single.splats.size(), 1000u);
    for (unsigned threads : {3u, 7u})
      expectSameSplats(single, classifySplats(v, tf, c, SIZE_MAX, threads), threads);
  }
}

// The mask against its definition, voxel by voxel: seeds are finite voxels whose value is
// visible, or which share a crossing (the values between them pass a visible one, neither
// end visible) with a 6-neighbour; kept are the voxels within the margin's ball of a seed.
TEST(ParallelClassification, MaskMatchesItsDefinition) {
  const Volume v = awkwardVolume();
  const TransferFunction tf = peakAndBand();
  const auto& d = v.dims();
  const double lo = v.minValue(), width = v.maxValue() - v.minValue();
  constexpr int kTable = 4096;  // the mask's table over the value range
  std::vector<bool> entry(kTable);
  for (int t = 0; t < kTable; ++t) entry[t] = tf.alphaAt(lo + width * t / (kTable - 1)) > 0.0;
  auto visibleBetween = [&](double a, double b) {  // any table entry between the two values
    const double x = (std::min(a, b) - lo) / width * (kTable - 1);
    const double y = (std::max(a, b) - lo) / width * (kTable - 1);
    for (int t = int(std::floor(x)); t <= int(std::ceil(y)); ++t)
      if (entry[size_t(t)]) return true;
    return false;
  };
  std::vector<uint8_t> seed(size_t(v.voxelCount()), 0);
  const int64_t steps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int64_t k = 0; k < d[2]; ++k)
    for (int64_t j = 0; j < d[1]; ++j)
      for (int64_t i = 0; i < d[0]; ++i) {
        const double a = v.value(i, j, k);
        if (!std::isfinite(a)) continue;
        bool s = visibleBetween(a, a);
        for (const auto& st : steps) {
          const int64_t p = i + st[0], q = j + st[1], r = k + st[2];
          if (s || p < 0 || q < 0 || r < 0 || p >= d[0] || q >= d[1] || r >= d[2]) continue;
          const double b = v.value(p, q, r);
          s = std::isfinite(b) && !visibleBetween(b, b) && visibleBetween(a, b);
        }
        seed[size_t(v.index(i, j, k))] = s;
      }
  const int margin = 2, marginSquared = 3;  // a radius between whole voxels
  const std::vector<uint8_t> mask = postClassificationMask(
      v, [&tf](double x) { return tf.alphaAt(x) > 0.0; }, marginSquared, 3);
  for (int64_t k = 0; k < d[2]; ++k)
    for (int64_t j = 0; j < d[1]; ++j)
      for (int64_t i = 0; i < d[0]; ++i) {
        bool near = false;
        for (int64_t c = -margin; c <= margin && !near; ++c)
          for (int64_t b = -margin; b <= margin && !near; ++b)
            for (int64_t a = -margin; a <= margin && !near; ++a) {
              const int64_t p = i + a, q = j + b, r = k + c;
              near = a * a + b * b + c * c <= marginSquared && p >= 0 && q >= 0 && r >= 0 &&
                     p < d[0] && q < d[1] && r < d[2] && seed[size_t(v.index(p, q, r))];
            }
        ASSERT_EQ(mask[size_t(v.index(i, j, k))], near ? 1 : 0) << i << "," << j << "," << k;
      }
}

TEST(ParallelClassification, SplatLimitHoldsAcrossThreads) {
  const Volume v = awkwardVolume();
  const auto above = [](double x) { return x > 50.0; };
  const size_t visible = SplatSet::build(v, above, 1, nullptr, SIZE_MAX, 1).size();
  ASSERT_GT(visible, 1000u);
  for (unsigned threads : {1u, 3u, 7u}) {
    EXPECT_EQ(SplatSet::build(v, above, 1, nullptr, visible, threads).size(), visible);
    EXPECT_THROW(SplatSet::build(v, above, 1, nullptr, visible - 1, threads), SplatLimitError);
    EXPECT_THROW(SplatSet::build(v, above, 1, nullptr, 10, threads), SplatLimitError);
  }
  // A coarse level (every other voxel) too.
  const SplatSet coarse = SplatSet::build(v, above, 2, nullptr, SIZE_MAX, 1);
  const SplatSet coarse3 = SplatSet::build(v, above, 2, nullptr, SIZE_MAX, 3);
  ASSERT_EQ(coarse.size(), coarse3.size());
  for (size_t n = 0; n < coarse.size(); ++n)
    ASSERT_TRUE(coarse.splats()[n].ij == coarse3.splats()[n].ij &&
                coarse.splats()[n].kValue == coarse3.splats()[n].kValue);
}

}  // namespace
}  // namespace ewa
