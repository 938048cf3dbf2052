// voxelsInBox and cropVolume: the voxels a world box keeps, against brute force over the centres.
#include "core/volume_crop.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace ewa {
namespace {

// A uint16 volume whose every voxel holds its own linear index, so a copy shows where it came from.
Volume numberedVolume(std::array<int64_t, 3> dims, glm::dvec3 spacing, glm::dvec3 origin) {
  std::vector<uint8_t> bytes(size_t(dims[0] * dims[1] * dims[2]) * 2);
  for (size_t n = 0; n < bytes.size() / 2; ++n) {
    const auto v = uint16_t(n);
    std::memcpy(&bytes[2 * n], &v, 2);
  }
  return Volume(dims, spacing, origin, ScalarType::UInt16, std::move(bytes));
}

// The smallest index range holding every centre inside the box, by visiting them all.
std::optional<VoxelRange> bruteForce(const Volume& v, glm::dvec3 lo, glm::dvec3 hi) {
  std::optional<VoxelRange> r;
  const auto& d = v.dims();
  for (int64_t k = 0; k < d[2]; ++k)
    for (int64_t j = 0; j < d[1]; ++j)
      for (int64_t i = 0; i < d[0]; ++i) {
        const glm::dvec3 p = v.worldPosition(double(i), double(j), double(k));
        if (glm::any(glm::lessThan(p, lo - 1e-9)) || glm::any(glm::greaterThan(p, hi + 1e-9)))
          continue;
        const std::array<int64_t, 3> at{i, j, k};
        if (!r) r = VoxelRange{at, at};
        for (size_t a = 0; a < 3; ++a) {
          r->low[a] = std::min(r->low[a], at[a]);
          r->high[a] = std::max(r->high[a], at[a]);
        }
      }
  return r;
}

void expectSameRange(const std::optional<VoxelRange>& a, const std::optional<VoxelRange>& b) {
  ASSERT_EQ(a.has_value(), b.has_value());
  if (!a) return;
  EXPECT_EQ(a->low, b->low);
  EXPECT_EQ(a->high, b->high);
}

TEST(VolumeCrop, KeepsTheVoxelsWhoseCentresLieInTheBox) {
  const Volume v = numberedVolume({10, 8, 6}, {1.0, 2.0, 0.5}, {10.0, 20.0, 30.0});
  // x 12.5..16 keeps i 3..6; y 22..30 (centres on both faces) keeps j 1..5; z 30.2..31.9 k 1..3.
  const auto r = voxelsInBox(v, {12.5, 22.0, 30.2}, {16.0, 30.0, 31.9});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->low, (std::array<int64_t, 3>{3, 1, 1}));
  EXPECT_EQ(r->high, (std::array<int64_t, 3>{6, 5, 3}));
  expectSameRange(r, bruteForce(v, {12.5, 22.0, 30.2}, {16.0, 30.0, 31.9}));

  const Volume c = cropVolume(v, *r);
  EXPECT_EQ(c.dims(), (std::array<int64_t, 3>{4, 5, 3}));
  EXPECT_EQ(c.spacing(), v.spacing());
  for (int64_t k = 0; k < 3; ++k)
    for (int64_t j = 0; j < 5; ++j)
      for (int64_t i = 0; i < 4; ++i) {
        EXPECT_EQ(c.value(i, j, k), v.value(i + 3, j + 1, k + 1));
        const glm::dvec3 was = v.worldPosition(double(i + 3), double(j + 1), double(k + 1));
        const glm::dvec3 is = c.worldPosition(double(i), double(j), double(k));
        EXPECT_NEAR(glm::distance(was, is), 0.0, 1e-12);
      }
  ASSERT_FALSE(c.notes().empty());
  EXPECT_EQ(c.notes().back(), "cropped to voxels 3-6, 1-5, 1-3 of 10 x 8 x 6");
}

TEST(VolumeCrop, ABoxBesideTheVolumeKeepsNothingAndOneAroundItKeepsAll) {
  const Volume v = numberedVolume({5, 5, 5}, glm::dvec3(1.0), glm::dvec3(0.0));
  EXPECT_FALSE(voxelsInBox(v, {5.5, 0.0, 0.0}, {9.0, 4.0, 4.0}));
  EXPECT_FALSE(voxelsInBox(v, {0.2, 0.0, 0.0}, {0.8, 4.0, 4.0}));  // between two centres
  const auto all = voxelsInBox(v, glm::dvec3(-3.0), glm::dvec3(40.0));
  ASSERT_TRUE(all);
  EXPECT_EQ(all->low, (std::array<int64_t, 3>{0, 0, 0}));
  EXPECT_EQ(all->high, (std::array<int64_t, 3>{4, 4, 4}));
  EXPECT_EQ(cropVolume(v, *all).bytes(), v.bytes());
}

TEST(VolumeCrop, AGridTurnedAgainstTheAxesAgreesWithBruteForce) {
  Volume v = numberedVolume({9, 7, 5}, {1.0, 1.5, 2.0}, {3.0, -2.0, 1.0});
  // A quarter turn about z and one about x: the grid's axes lie along other world axes.
  const glm::dmat3 turn =
      glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::half_pi<double>(), glm::dvec3(0, 0, 1))) *
      glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::half_pi<double>(), glm::dvec3(1, 0, 0)));
  v.setDirection(turn, true);
  const glm::dvec3 lo = v.worldBoundsMin(), hi = v.worldBoundsMax();
  for (const double f : {0.0, 0.13, 0.31, 0.5}) {
    const glm::dvec3 a = lo + f * (hi - lo), b = hi - 0.5 * f * (hi - lo);
    expectSameRange(voxelsInBox(v, a, b), bruteForce(v, a, b));
  }
  const auto r = voxelsInBox(v, lo + 0.3 * (hi - lo), hi);
  ASSERT_TRUE(r);
  const Volume c = cropVolume(v, *r);
  EXPECT_EQ(c.direction(), v.direction());
  EXPECT_TRUE(c.patientFrame());
  EXPECT_NEAR(glm::distance(c.worldPosition(1, 2, 1),
                            v.worldPosition(double(r->low[0] + 1), double(r->low[1] + 2),
                                            double(r->low[2] + 1))),
              0.0, 1e-12);
}

TEST(VolumeCrop, ARangeOutsideTheVolumeThrows) {
  const Volume v = numberedVolume({4, 4, 4}, glm::dvec3(1.0), glm::dvec3(0.0));
  EXPECT_THROW(cropVolume(v, VoxelRange{{0, 0, 0}, {4, 3, 3}}), std::invalid_argument);
  EXPECT_THROW(cropVolume(v, VoxelRange{{2, 0, 0}, {1, 3, 3}}), std::invalid_argument);
  EXPECT_THROW(cropVolume(v, VoxelRange{{-1, 0, 0}, {1, 3, 3}}), std::invalid_argument);
}

}  // namespace
}  // namespace ewa
