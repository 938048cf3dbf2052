// The ray normals' gradient texels: central differences per index step, packed linearly in 10
// bits, and the trilinear read the shader makes of them.
#include "core/gradient_volume.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace ewa {
namespace {

// A float volume of `dims` and `spacing` with value f(i, j, k) at each voxel.
template <typename F>
Volume floatField(std::array<int64_t, 3> dims, glm::dvec3 spacing, F f) {
  std::vector<float> v;
  for (int64_t k = 0; k < dims[2]; ++k)
    for (int64_t j = 0; j < dims[1]; ++j)
      for (int64_t i = 0; i < dims[0]; ++i) v.push_back(float(f(double(i), double(j), double(k))));
  std::vector<uint8_t> bytes(v.size() * sizeof(float));
  std::memcpy(bytes.data(), v.data(), bytes.size());
  return Volume(dims, spacing, glm::dvec3(0.0), ScalarType::Float32, std::move(bytes));
}

constexpr double kStep = 1.0 / 511.0;  // one 10-bit level of a component in [-1, 1]

// A linear field's gradient per index step is its slope per index, whatever the spacing (the
// shader turns it into camera space through the camera-to-index matrix): (2, -3, 1) / 3 after
// the scale, at every voxel, the border's one-sided differences included.
TEST(GradientVolume, LinearFieldPacksItsSlopePerIndexStep) {
  const Volume v = floatField({5, 4, 3}, {0.5, 2.0, 3.0},
                              [](double i, double j, double k) { return 2.0 * i - 3.0 * j + k; });
  const PackedGradients g = packGradients(v, GradientMode::Central, 2);
  EXPECT_EQ(g.dims, v.dims());
  EXPECT_NEAR(g.scale, 3.0, 1e-9);
  ASSERT_EQ(g.texels.size(), size_t(5 * 4 * 3));
  for (uint32_t texel : g.texels) {
    const glm::dvec3 d = unpackGradient(texel);
    EXPECT_NEAR(d.x, 2.0 / 3.0, kStep);
    EXPECT_NEAR(d.y, -1.0, kStep);
    EXPECT_NEAR(d.z, 1.0 / 3.0, kStep);
    EXPECT_EQ(texel >> 30, 0u);  // alpha unused
  }
  EXPECT_EQ(packGradients(v, GradientMode::Central, 1).texels, g.texels);  // any thread count
}

// The packed gradients are volumeGradient's (the voxel normals' and the C++ reference's) per
// index step, central and smooth, at every voxel of an uneven field with a NaN in it, borders
// included; the scale is the central differences' largest component (a smooth gradient
// averages them).
TEST(GradientVolume, TexelsAreVolumeGradientsPerIndexStep) {
  const glm::dvec3 spacing(0.5, 2.0, 3.0);
  const Volume v = floatField({7, 5, 4}, spacing, [](double i, double j, double k) {
    if (i == 3 && j == 2 && k == 1) return std::nan("");
    return std::sin(1.7 * i + 0.3 * j * j) * 40.0 + 9.0 * k - j;
  });
  for (GradientMode mode : {GradientMode::Central, GradientMode::Smooth}) {
    const PackedGradients g = packGradients(v, mode, 0);
    double most = 0.0;
    for (int64_t k = 0; k < 4; ++k)
      for (int64_t j = 0; j < 5; ++j)
        for (int64_t i = 0; i < 7; ++i) {
          const glm::dvec3 central = volumeGradient(v, i, j, k, GradientMode::Central) * spacing;
          most = std::max({most, std::abs(central.x), std::abs(central.y), std::abs(central.z)});
          const glm::dvec3 want = volumeGradient(v, i, j, k, mode) * spacing;
          const glm::dvec3 got = unpackGradient(g.texels[size_t(v.index(i, j, k))]) * g.scale;
          for (int a = 0; a < 3; ++a)
            EXPECT_NEAR(got[a], want[a], 0.5 * kStep * g.scale)
                << gradientModeName(mode) << " at " << i << " " << j << " " << k;
        }
    EXPECT_NEAR(g.scale, most, 1e-9 * most);
  }
}

// Between voxels the read is trilinear in the texels, clamped at the edge: a quadratic field's
// x-gradient 2i runs linearly between the voxel centres.
TEST(GradientVolume, SampleIsTrilinearBetweenVoxelCentres) {
  const Volume v =
      floatField({6, 3, 3}, glm::dvec3(1.0), [](double i, double, double) { return i * i; });
  const PackedGradients g = packGradients(v, GradientMode::Central, 0);
  // Central differences of i^2: 2i inside, one-sided at the ends (1 at i = 0, 9 at i = 5).
  EXPECT_NEAR(g.scale, 9.0, 1e-9);
  for (double x : {1.0, 1.25, 2.5, 3.75}) {
    EXPECT_NEAR(sampleGradient(g, {x, 1.0, 1.0}).x, 2.0 * x / 9.0, kStep) << x;
    EXPECT_NEAR(sampleGradient(g, {x, 0.3, 1.7}).x, 2.0 * x / 9.0, kStep) << x;
  }
  EXPECT_NEAR(sampleGradient(g, {-3.0, 1.0, 1.0}).x, 1.0 / 9.0, kStep);  // the edge's texel
  EXPECT_NEAR(sampleGradient(g, {4.5, 1.0, 1.0}).x, 8.5 / 9.0, kStep);
  EXPECT_NEAR(sampleGradient(g, {2.0, 1.0, 1.0}).y, 0.0, kStep);
}

// A constant field has no gradient: texels of exactly zero (level 512), not NaN nor a level's
// rounding (which the shader would normalize into a direction), and a scale of 1.
TEST(GradientVolume, ConstantFieldHasNoGradient) {
  const Volume v =
      floatField({3, 3, 3}, glm::dvec3(1.0), [](double, double, double) { return 7.0; });
  const PackedGradients g = packGradients(v, GradientMode::Smooth, 0);
  EXPECT_EQ(g.scale, 1.0);
  for (uint32_t texel : g.texels) {
    EXPECT_EQ(unpackGradient(texel), glm::dvec3(0.0));
    EXPECT_EQ(texel, 512u | 512u << 10 | 512u << 20);
  }
}

}  // namespace
}  // namespace ewa
