// Unit tests of the Volume class: storage, statistics, world placement.
#include "core/volume.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace ewa {
namespace {

TEST(Volume, RangeAndHistogramOfUInt16) {
  std::vector<uint8_t> bytes(2 * 3 * 2 * 2);
  for (int n = 0; n < 12; ++n) {
    uint16_t v = static_cast<uint16_t>(100 + n * 10);
    std::memcpy(bytes.data() + 2 * n, &v, 2);
  }
  Volume vol({2, 3, 2}, {1.0, 2.0, 3.0}, {5.0, 0.0, 0.0}, ScalarType::UInt16, bytes);
  EXPECT_EQ(vol.voxelCount(), 12);
  EXPECT_DOUBLE_EQ(vol.minValue(), 100.0);
  EXPECT_DOUBLE_EQ(vol.maxValue(), 210.0);
  EXPECT_DOUBLE_EQ(vol.value(1, 2, 1), 100.0 + 10.0 * (1 + 2 * 2 + 6));
  uint64_t total = 0;
  for (auto c : vol.histogram()) total += c;
  EXPECT_EQ(total, 12u);
  EXPECT_EQ(vol.histogram().front(), 1u);
  EXPECT_EQ(vol.histogram().back(), 1u);
  const glm::dvec3 p = vol.worldPosition(1, 2, 1);
  EXPECT_DOUBLE_EQ(p.x, 6.0);
  EXPECT_DOUBLE_EQ(p.y, 4.0);
  EXPECT_DOUBLE_EQ(p.z, 3.0);
}

TEST(Volume, FloatRangeSkipsNaNAndInfinity) {
  const float vals[4] = {1.5f, NAN, INFINITY, -2.0f};
  std::vector<uint8_t> bytes(sizeof vals);
  std::memcpy(bytes.data(), vals, sizeof vals);
  Volume vol({4, 1, 1}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::Float32, bytes);
  EXPECT_DOUBLE_EQ(vol.minValue(), -2.0);
  EXPECT_DOUBLE_EQ(vol.maxValue(), 1.5);
}

// Large enough for the statistics to be split between threads: the range's extremes and the
// non-finite voxels sit in different chunks, and every bin is counted once.
TEST(Volume, StatisticsOfALargeVolumeMatchOneLoop) {
  const int64_t n = 64 * 64 * 80;
  std::vector<float> values(static_cast<size_t>(n));
  for (int64_t i = 0; i < n; ++i) values[size_t(i)] = float(std::sin(0.001 * double(i)) * 50.0);
  values[17] = NAN;
  values[size_t(n / 2)] = -INFINITY;
  values[size_t(n - 3)] = -75.0f;  // the minimum, near the end
  values[5] = 120.0f;              // the maximum, near the start
  std::vector<uint8_t> bytes(values.size() * sizeof(float));
  std::memcpy(bytes.data(), values.data(), bytes.size());
  Volume vol({64, 64, 80}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::Float32, bytes);
  EXPECT_DOUBLE_EQ(vol.minValue(), -75.0);
  EXPECT_DOUBLE_EQ(vol.maxValue(), 120.0);
  std::vector<uint64_t> expected(Volume::histogramBins(), 0);
  for (float v : values) {
    if (!std::isfinite(v)) continue;
    const int bin = int((double(v) + 75.0) / 195.0 * Volume::histogramBins());
    expected[size_t(std::clamp(bin, 0, Volume::histogramBins() - 1))]++;
  }
  EXPECT_EQ(vol.histogram(), expected);
  uint64_t total = 0;
  for (uint64_t c : vol.histogram()) total += c;
  EXPECT_EQ(total, uint64_t(n - 2));
}

TEST(Volume, RejectsMismatchedSizes) {
  EXPECT_THROW(Volume({2, 2, 2}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::Int16,
                      std::vector<uint8_t>(15)),
               std::invalid_argument);
  EXPECT_THROW(Volume({2, 2, 2}, glm::dvec3(0.0), glm::dvec3(0.0), ScalarType::UInt8,
                      std::vector<uint8_t>(8)),
               std::invalid_argument);
}

}  // namespace
}  // namespace ewa
