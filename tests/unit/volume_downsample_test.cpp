// Unit tests of the level-of-detail volume: box averages, mass, odd sizes, spacing, origin.
#include "core/volume_downsample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace ewa {
namespace {

// A float32 volume whose voxel (i,j,k) holds f(i,j,k).
template <typename F>
Volume makeVolume(std::array<int64_t, 3> d, glm::dvec3 spacing, F f) {
  std::vector<uint8_t> bytes(size_t(d[0] * d[1] * d[2]) * 4);
  size_t n = 0;
  for (int64_t k = 0; k < d[2]; ++k)
    for (int64_t j = 0; j < d[1]; ++j)
      for (int64_t i = 0; i < d[0]; ++i, ++n) {
        const float v = float(f(i, j, k));
        std::memcpy(bytes.data() + n * 4, &v, 4);
      }
  return Volume(d, spacing, glm::dvec3(10, 20, 30), ScalarType::Float32, std::move(bytes));
}

double sum(const Volume& v) {
  double s = 0.0;
  for (int64_t n = 0; n < v.voxelCount(); ++n) s += v.valueAt(n);
  return s;
}

TEST(Downsample, EvenDimsAverageBlocksAndKeepMass) {
  const Volume fine = makeVolume({8, 6, 4}, {1.0, 0.5, 2.0}, [](int64_t i, int64_t j, int64_t k) {
    return i * 7 + j * j + 3 * k;
  });
  const Volume coarse = downsampleVolume(fine, 2);
  EXPECT_EQ(coarse.dims(), (std::array<int64_t, 3>{4, 3, 2}));
  EXPECT_EQ(coarse.spacing(), glm::dvec3(2.0, 1.0, 4.0));
  // Voxel (1,2,0) averages fine voxels i in {2,3}, j in {4,5}, k in {0,1}.
  double expected = 0.0;
  for (int i = 2; i < 4; ++i)
    for (int j = 4; j < 6; ++j)
      for (int k = 0; k < 2; ++k) expected += (i * 7 + j * j + 3 * k) / 8.0;
  EXPECT_NEAR(coarse.value(1, 2, 0), expected, 1e-5);
  // Mass: sum of values times voxel volume is kept; so is the mean.
  const double fineVoxel = 1.0 * 0.5 * 2.0, coarseVoxel = 2.0 * 1.0 * 4.0;
  EXPECT_NEAR(sum(coarse) * coarseVoxel, sum(fine) * fineVoxel, 1e-6 * sum(fine));
  EXPECT_NEAR(sum(coarse) / coarse.voxelCount(), sum(fine) / fine.voxelCount(), 1e-4);
}

TEST(Downsample, OriginMovesToFirstBlockCentreSoBoundsStay) {
  const Volume fine = makeVolume({8, 8, 8}, {1.0, 2.0, 0.5}, [](auto, auto, auto) { return 1; });
  const Volume coarse = downsampleVolume(fine, 2);
  EXPECT_EQ(coarse.origin(), fine.origin() + 0.5 * fine.spacing());
  // The centre of the box through the voxel centres does not move.
  EXPECT_EQ(0.5 * (coarse.boundsMin() + coarse.boundsMax()),
            0.5 * (fine.boundsMin() + fine.boundsMax()));
  const Volume quarter = downsampleVolume(fine, 4);
  EXPECT_EQ(quarter.spacing(), 4.0 * fine.spacing());
  EXPECT_EQ(quarter.origin(), fine.origin() + 1.5 * fine.spacing());
}

TEST(Downsample, CoarseLevelsKeepTheSourcesDataBox) {
  // Where the field ends (post-classified slabs): the fine voxel-centre box, in every level's
  // own indices, so a coarse picture's outline does not shrink by half a coarse voxel a face.
  Volume fine = makeVolume({10, 7, 1}, {1.0, 2.0, 0.5}, [](auto, auto, auto) { return 1; });
  fine.setDirection(glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1)),
                    false);
  const DataBox fineBox = fine.indexDataBox();
  EXPECT_EQ(fineBox.low, glm::dvec3(0.0, 0.0, -0.5));  // the flat axis: the voxel's extent
  EXPECT_EQ(fineBox.high, glm::dvec3(9.0, 6.0, 0.5));
  const Volume quarter = downsampleVolume(fine, 4);
  const Volume chained = downsampleVolume(downsampleVolume(fine, 2), 2);
  for (const Volume* coarse : {&quarter, &chained}) {
    const DataBox box = coarse->indexDataBox();
    for (bool high : {false, true}) {
      const glm::dvec3 f = high ? fineBox.high : fineBox.low, c = high ? box.high : box.low;
      const glm::dvec3 want = fine.worldPosition(f.x, f.y, f.z);
      const glm::dvec3 got = coarse->worldPosition(c.x, c.y, c.z);
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(got[a], want[a], 1e-12) << high << " " << a;
    }
  }
  // Beyond the coarse voxel-centre box: 1.5 fine voxels (0.375 coarse ones) in x.
  EXPECT_NEAR(quarter.indexDataBox().low.x, -0.375, 1e-12);
}

TEST(Downsample, OddDimsAverageTheVoxelsThatRemain) {
  const Volume fine =
      makeVolume({5, 3, 1}, {1, 1, 1}, [](int64_t i, int64_t j, int64_t) { return 10 * i + j; });
  const Volume coarse = downsampleVolume(fine, 2);
  // ceil(5/2) = 3, ceil(3/2) = 2, and a single slice stays a single slice at its spacing.
  EXPECT_EQ(coarse.dims(), (std::array<int64_t, 3>{3, 2, 1}));
  EXPECT_EQ(coarse.spacing(), glm::dvec3(2, 2, 1));
  // Last block along x holds only i = 4; along y only j = 2.
  EXPECT_NEAR(coarse.value(2, 0, 0), (40 + 41) / 2.0, 1e-5);
  EXPECT_NEAR(coarse.value(2, 1, 0), 42.0, 1e-5);
  EXPECT_NEAR(coarse.value(0, 1, 0), (2 + 12) / 2.0, 1e-5);
  // The mean over the voxels is not the mean of the blocks when blocks differ in size; the
  // mass-weighted sum is: each coarse value times its block's voxel count.
  const double weighted = coarse.value(0, 0, 0) * 4 + coarse.value(1, 0, 0) * 4 +
                          coarse.value(2, 0, 0) * 2 + coarse.value(0, 1, 0) * 2 +
                          coarse.value(1, 1, 0) * 2 + coarse.value(2, 1, 0) * 1;
  EXPECT_NEAR(weighted, sum(fine), 1e-4);
}

TEST(Downsample, NativeTypesBecomeFloatMeansWithoutRounding) {
  std::vector<uint8_t> bytes = {0, 1, 0, 0, 0, 0, 0, 0};  // one voxel of 1 in a 2x2x2 block
  const Volume fine({2, 2, 2}, glm::dvec3(1), glm::dvec3(0), ScalarType::UInt8, bytes);
  const Volume coarse = downsampleVolume(fine, 2);
  EXPECT_EQ(coarse.type(), ScalarType::Float32);
  EXPECT_EQ(coarse.voxelCount(), 1);
  EXPECT_DOUBLE_EQ(coarse.value(0, 0, 0), 0.125);
}

TEST(Downsample, NanVoxelsAreLeftOutOfTheMean) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Volume fine = makeVolume({4, 1, 1}, {1, 1, 1}, [nan](int64_t i, int64_t, int64_t) {
    return i == 0 ? 6.0 : (i == 1 ? nan : (i == 2 ? nan : nan));
  });
  const Volume coarse = downsampleVolume(fine, 2);
  EXPECT_DOUBLE_EQ(coarse.value(0, 0, 0), 6.0);
  EXPECT_TRUE(std::isnan(coarse.value(1, 0, 0)));
}

TEST(Downsample, FactorOneCopiesAndBadFactorsThrow) {
  const Volume fine = makeVolume({3, 3, 3}, {1, 1, 1},
                                 [](int64_t i, int64_t j, int64_t k) { return i + 3 * j + 9 * k; });
  const Volume same = downsampleVolume(fine, 1);
  EXPECT_EQ(same.dims(), fine.dims());
  EXPECT_EQ(same.origin(), fine.origin());
  for (int64_t n = 0; n < fine.voxelCount(); ++n) EXPECT_EQ(same.valueAt(n), fine.valueAt(n));
  EXPECT_THROW(downsampleVolume(fine, 0), std::invalid_argument);
  EXPECT_THROW(downsampleVolume(Volume(), 2), std::invalid_argument);
}

}  // namespace
}  // namespace ewa
