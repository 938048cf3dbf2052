// Unit tests of classification into splats and of the slab partition.
#include "core/splat_set.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <set>

#include "core/slab_partition.h"

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
  EXPECT_EQ(SplatSet::build(
                vol, [](double) { return true; }, 2)
                .size(),
            64u);
}

TEST(SlabPartition, ListsEachSplatInEverySlabItsDepthExtentOverlaps) {
  const Volume vol = rampVolume(10);
  const SplatSet set = SplatSet::build(vol, [](double) { return true; });
  // Looking down -z from z = 20: depth = 20 - k.
  const glm::dmat4 view =
      glm::lookAt(glm::dvec3(4.5, 4.5, 20), glm::dvec3(4.5, 4.5, 0), glm::dvec3(0, 1, 0));
  DepthExtent extent;  // cutoff 4, unit spacing: kernels reach sqrt(4 * 1) = 2 in depth
  SlabPartition part;
  part.build(set, {}, vol.origin(), view, 2.0, 12.5, extent);
  // Depths 11..20 minus those <= 12.5 (k = 8, 9): k = 0..7, depths 13..20, extents
  // [d - 2, d + 2] from 11 to 22: slabs [11, 13), [13, 15), ..., [21, 23).
  ASSERT_EQ(part.slabs().size(), 6u);
  EXPECT_EQ(part.splatCount(), 800u);
  std::map<uint32_t, std::vector<size_t>> slabsOf;
  size_t index = 0;
  double prev = -1.0;
  for (const Slab& slab : part.slabs()) {
    EXPECT_NEAR(slab.nearDepth, 11.0 + 2.0 * index, 1e-9);
    EXPECT_NEAR(slab.farDepth, slab.nearDepth + 2.0, 1e-9);
    EXPECT_GT(slab.nearDepth, prev);
    prev = slab.nearDepth;
    for (uint32_t m = slab.first; m < slab.first + slab.count; ++m) {
      const uint32_t entry = part.order()[m];
      const uint32_t splat = entry & SlabPartition::kIndexMask;
      const double depth = 20.0 - SplatSet::k(set.splats()[splat]);
      // The slab overlaps the kernel's extent; the flags mark its first and last slab.
      EXPECT_LT(slab.nearDepth, depth + 2.0 + 1e-6);
      EXPECT_GT(slab.farDepth, depth - 2.0 - 1e-6);
      EXPECT_EQ((entry & SlabPartition::kFirstSlab) != 0, slab.nearDepth <= depth - 2.0);
      EXPECT_EQ((entry & SlabPartition::kLastSlab) != 0, slab.farDepth > depth + 2.0);
      slabsOf[splat].push_back(index);
    }
    ++index;
  }
  ASSERT_EQ(slabsOf.size(), 800u);
  for (const auto& [splat, list] : slabsOf) {
    // Consecutive slabs, covering [d - 2, d + 2]: 2 or 3 slabs of thickness 2.
    EXPECT_GE(list.size(), 2u);
    EXPECT_LE(list.size(), 3u);
    for (size_t q = 1; q < list.size(); ++q) EXPECT_EQ(list[q], list[q - 1] + 1);
  }
}

TEST(SlabPartition, KernelReachScalesWithKernelWidth) {
  const Volume vol = rampVolume(10);
  const SplatSet set = SplatSet::build(vol, [](double) { return true; });
  const glm::dmat4 view =
      glm::lookAt(glm::dvec3(4.5, 4.5, 20), glm::dvec3(4.5, 4.5, 0), glm::dvec3(0, 1, 0));
  DepthExtent extent;
  extent.kernelWidth = 0.5;  // sigma half a voxel: kernels reach sqrt(4) * 0.5 = 1 in depth
  SlabPartition part;
  part.build(set, {}, vol.origin(), view, 1.0, 0.5, extent);
  // Depths 11..20, extents [d - 1, d + 1] from 10 to 21: slabs [10, 11), ..., [21, 22), each
  // kernel listed in the three its closed extent touches.
  ASSERT_EQ(part.slabs().size(), 12u);
  EXPECT_NEAR(part.slabs().front().nearDepth, 10.0, 1e-9);
  EXPECT_EQ(part.order().size(), 3u * 1000u);
  extent.kernelWidth = 1.5;  // reach 3: [8, 23], seven slabs a kernel
  part.build(set, {}, vol.origin(), view, 1.0, 0.5, extent);
  EXPECT_NEAR(part.slabs().front().nearDepth, 8.0, 1e-9);
  EXPECT_EQ(part.slabs().size(), 16u);
  EXPECT_EQ(part.order().size(), 7u * 1000u);
}

}  // namespace
}  // namespace ewa
