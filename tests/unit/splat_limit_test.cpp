// SplatSet's limit: more visible voxels than the caller's buffer holds fail before the list grows.
#include <gtest/gtest.h>

#include "core/splat_set.h"

namespace ewa {
namespace {

Volume ramp(int n) {
  std::vector<uint8_t> bytes(size_t(n) * n * n);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = uint8_t(i % 200);
  return Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, bytes);
}

TEST(SplatLimit, ExactlyTheLimitFitsOneMoreThrows) {
  const Volume v = ramp(6);
  const auto above50 = [](double x) { return x > 50.0; };
  const size_t visible = SplatSet::build(v, above50).size();
  ASSERT_GT(visible, 10u);
  EXPECT_EQ(SplatSet::build(v, above50, 1, nullptr, visible).size(), visible);
  EXPECT_THROW(SplatSet::build(v, above50, 1, nullptr, visible - 1), SplatLimitError);
  EXPECT_THROW(SplatSet::build(v, above50, 1, nullptr, 0), SplatLimitError);
  // Nothing visible: no limit is too small.
  EXPECT_EQ(SplatSet::build(
                v, [](double) { return false; }, 1, nullptr, 0)
                .size(),
            0u);
}

}  // namespace
}  // namespace ewa
