// Unit tests of the Volume class: storage, statistics, world placement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/volume.h"

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
