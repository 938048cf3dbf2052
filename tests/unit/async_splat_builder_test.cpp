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
  return classifySplats(v, tf, {}).splats.size();
}

TEST(AsyncSplatBuilder, BuildsTheSameSetAsADirectBuild) {
  const Volume v = rampVolume(32);
  AsyncSplatBuilder builder;
  EXPECT_FALSE(builder.busy());
  EXPECT_FALSE(builder.poll().has_value());
  builder.request(v, above(100.0));
  EXPECT_TRUE(builder.busy());
  std::optional<BuiltSplats> built;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!built && std::chrono::steady_clock::now() < deadline) {
    built = builder.poll();  // never blocks
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_TRUE(built.has_value());
  EXPECT_FALSE(builder.busy());
  const SplatSet* set = &built->splats.splats;
  EXPECT_EQ(built->splats.attributes.size(), set->size());
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
  // A splat limit below what the first request keeps: the error comes out of finish().
  AsyncSplatBuilder limited;
  limited.request(v, above(0.0), {}, 10);
  EXPECT_ANY_THROW(limited.finish());
  Classification smooth;
  smooth.gradient = GradientMode::Smooth;
  builder.request(v, above(220.0), smooth);
  const std::optional<BuiltSplats> last = builder.finish();
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->splats.splats.size(), directCount(v, above(220.0)));
  EXPECT_EQ(last->classification, smooth);
  EXPECT_FALSE(builder.busy());
  EXPECT_FALSE(builder.finish().has_value());
}

}  // namespace
}  // namespace ewa
