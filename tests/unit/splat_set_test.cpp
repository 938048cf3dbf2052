// Unit tests of classification into splats and of the slab partition.
#include <gtest/gtest.h>

#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "core/slab_partition.h"
#include "core/splat_set.h"

namespace ewa {
namespace {

Volume rampVolume(int n) {
  std::vector<uint8_t> bytes(size_t(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) bytes[i + n * (j + n * k)] = uint8_t(i * 255 / (n - 1));
  return Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, bytes);
}

TEST(SplatSet, KeepsOnlyVisibleVoxelsWithTheirIndicesAndValues) {
  const Volume vol = rampVolume(8);
  const SplatSet set = SplatSet::build(vol, [](double v) { return v > 200.0; });
  // i = 7 has value 255 (visible), i = 6 has 218 (visible), i = 5 has 182 (not).
  EXPECT_EQ(set.size(), 2u * 64u);
  for (const auto& s : set.splats()) {
    EXPECT_GE(SplatSet::i(s), 6u);
    const double value = vol.value(SplatSet::i(s), SplatSet::j(s), SplatSet::k(s));
    EXPECT_NEAR(SplatSet::normalizedValue(s), value / 255.0, 1e-4);
  }
  EXPECT_EQ(SplatSet::build(vol, [](double) { return false; }).size(), 0u);
  EXPECT_EQ(SplatSet::build(vol, [](double) { return true; }, 2).size(), 64u);
}

TEST(SlabPartition, BucketsByCameraDepthFrontToBack) {
  const Volume vol = rampVolume(10);
  const SplatSet set = SplatSet::build(vol, [](double) { return true; });
  // Looking down -z from z = 20: depth = 20 - k.
  const glm::dmat4 view = glm::lookAt(glm::dvec3(4.5, 4.5, 20), glm::dvec3(4.5, 4.5, 0),
                                      glm::dvec3(0, 1, 0));
  SlabPartition part;
  part.build(set, vol.origin(), vol.spacing(), view, 2.0, 12.5);
  // Depths 11..20 minus those <= 12.5 (k = 8, 9): k = 0..7, depths 13..20 in 4 slabs.
  ASSERT_EQ(part.slabs().size(), 4u);
  EXPECT_EQ(part.order().size(), 800u);
  double prev = -1.0;
  std::set<uint32_t> seen;
  for (const Slab& slab : part.slabs()) {
    EXPECT_EQ(slab.count, 200u);
    EXPECT_GT(slab.nearDepth, prev);
    prev = slab.nearDepth;
    for (uint32_t m = slab.first; m < slab.first + slab.count; ++m) {
      const auto& s = set.splats()[part.order()[m]];
      const double depth = 20.0 - SplatSet::k(s);
      EXPECT_GE(depth, slab.nearDepth - 1e-6);
      EXPECT_LT(depth, slab.nearDepth + 2.0);
      seen.insert(part.order()[m]);
    }
  }
  EXPECT_EQ(seen.size(), 800u);
}

}  // namespace
}  // namespace ewa
