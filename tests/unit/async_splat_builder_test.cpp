// Unit tests of AsyncSplatBuilder: the worker's set equals a direct build; newer requests win.
#include "core/async_splat_builder.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace ewa {
namespace {

Volume rampVolume(int n) {
  std::vector<uint8_t> bytes(size_t(n) * n * n);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = uint8_t(i % 256);
  return Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, bytes);
}

TransferFunction above(double threshold) {
  TransferFunction tf;
  tf.opacity = {{threshold, 0.0}, {threshold + 1e-3, 0.5}};
  return tf;
}

size_t directCount(const Volume& v, const TransferFunction& tf) {
  return SplatSet::build(v, [&](double x) { return tf.alphaAt(x) > 0.0; }).size();
}

TEST(AsyncSplatBuilder, BuildsTheSameSetAsADirectBuild) {
  const Volume v = rampVolume(32);
  AsyncSplatBuilder builder;
  EXPECT_FALSE(builder.busy());
  EXPECT_FALSE(builder.poll().has_value());
  builder.request(v, above(100.0));
  EXPECT_TRUE(builder.busy());
  std::optional<SplatSet> set;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!set && std::chrono::steady_clock::now() < deadline) {
    set = builder.poll();  // never blocks
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_TRUE(set.has_value());
  EXPECT_FALSE(builder.busy());
  const SplatSet direct = SplatSet::build(v, [](double x) { return x > 100.0; });
  ASSERT_EQ(set->size(), direct.size());
  EXPECT_GT(set->size(), 0u);
  for (size_t i = 0; i < set->size(); ++i) {
    EXPECT_EQ(set->splats()[i].ij, direct.splats()[i].ij);
    EXPECT_EQ(set->splats()[i].kValue, direct.splats()[i].kValue);
  }
}

TEST(AsyncSplatBuilder, TheNewestRequestIsTheLastSetHandedOver) {
  const Volume v = rampVolume(32);
  AsyncSplatBuilder builder;
  // Many requests while the first builds (a drag): the last one handed over is the newest.
  for (double t = 0.0; t <= 200.0; t += 20.0) builder.request(v, above(t));
  const std::optional<SplatSet> last = builder.finish();
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->size(), directCount(v, above(200.0)));
  EXPECT_FALSE(builder.busy());
  EXPECT_FALSE(builder.finish().has_value());
}

}  // namespace
}  // namespace ewa
