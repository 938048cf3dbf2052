// Defaults that follow the data: a mask's structures one voxel thin stay visible with the
// transfer function made for it, and slabs follow the spacing along the view, so a stack of thick
// slices seen face-on is not cut into slabs as thin as its pixels.
#include <algorithm>
#include <cmath>

#include "core/slab_partition.h"
#include "core/transfer_function.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class DataShapedDefaults : public RenderFixture {};

// Lines one voxel thin along the three axes through a 40^3 mask of 0 and 255, as an ImageJ
// skeleton is stored.
Volume skeleton() {
  return makeVolume(40, 40, 40, glm::dvec3(1.0), [](int i, int j, int k) {
    const int on = (i == 20) + (j == 20) + (k == 20);
    return on >= 2 && i > 4 && j > 4 && k > 4 && i < 35 && j < 35 && k < 35;
  });
}

Camera framing(const Volume& v, glm::dvec3 from) {
  const glm::dvec3 centre = 0.5 * (v.worldBoundsMin() + v.worldBoundsMax());
  Camera cam;
  cam.focalPoint = centre;
  cam.position = centre + from;
  cam.viewUp = std::abs(from.z) > std::abs(from.y) ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  return cam;
}

int brightest(const Image8& img) {
  int peak = 0;
  for (size_t n = 0; n < img.pixels.size(); ++n) peak = std::max(peak, int(img.pixels[n]));
  return peak;
}

double meanLevel(const Image8& img) {
  double sum = 0.0;
  for (const uint8_t p : img.pixels) sum += p;
  return sum / double(img.pixels.size());
}

TEST_F(DataShapedDefaults, AOneVoxelSkeletonIsVisibleWithTheDefaultTransferFunction) {
  Volume v = skeleton();
  // makeVolume's voxels are 200: scale to a mask of 0 and 255.
  std::vector<uint8_t> bytes = v.bytes();
  for (uint8_t& b : bytes) b = b ? 255 : 0;
  const Volume mask(v.dims(), v.spacing(), v.origin(), ScalarType::UInt8, std::move(bytes));
  const TransferFunction tf = defaultTransferFunction(mask);
  EXPECT_EQ(tf.alphaAt(0.0), 0.0);
  EXPECT_GT(tf.alphaAt(0.3 * 255.0), 0.5) << "a thin line's field peaks near a third";
  renderer()->setVolume(mask);
  renderer()->setTransferFunction(tf);
  renderer()->render(framing(mask, {0.0, -90.0, 0.0}), RenderSettings{}, 128, 128);
  const int peak = brightest(renderer()->readImage());
  std::printf("skeleton's brightest level %d\n", peak);
  EXPECT_GT(peak, 120);
}

TEST_F(DataShapedDefaults, ThickSlicesSeenFaceOnAreSlabbedByTheirThickness) {
  // 7 mm slices of 0.86 mm pixels, a ball of them; seen along z, a slab is two slices deep.
  const glm::dvec3 spacing(0.86, 0.86, 7.0);
  const Volume v = makeVolume(64, 64, 12, spacing, [](int i, int j, int k) {
    const double x = (i - 31.5) * 0.86, y = (j - 31.5) * 0.86, z = (k - 5.5) * 7.0;
    return x * x + y * y + z * z < 26.0 * 26.0;
  });
  renderer()->setVolume(v);
  renderer()->setTransferFunction(whiteTf(0.05, 1.0));
  RenderSettings settings;
  const Camera faceOn = framing(v, {0.0, 0.0, 200.0});
  renderer()->render(faceOn, settings, 96, 96);
  const size_t thick = renderer()->stats().slabs;
  const Image8 picture = renderer()->readImage();
  // A quarter of a slice deep: about the old slabs of twice the smallest spacing.
  settings.slabThickness = 0.25;
  renderer()->render(faceOn, settings, 96, 96);
  const size_t thin = renderer()->stats().slabs;
  const Image8 fine = renderer()->readImage();
  std::printf("face-on slabs: %zu (default), %zu (a quarter slice)\n", thick, thin);
  EXPECT_LE(thick, 10u);  // 84 mm deep, 14 mm slabs, and the kernels' reach
  EXPECT_GE(thin, 4 * thick);
  EXPECT_NEAR(meanLevel(picture), meanLevel(fine), 0.05 * meanLevel(fine) + 0.5);
  // Isotropic voxels: the unit is the spacing, as before.
  EXPECT_DOUBLE_EQ(viewSpacing(faceOn.rotation(), glm::dvec3(0.5)), 0.5);
  EXPECT_NEAR(viewSpacing(faceOn.rotation(), spacing), 7.0, 7.0 * 0.05);
  EXPECT_NEAR(viewSpacing(framing(v, {0.0, -200.0, 0.0}).rotation(), spacing), 0.86, 0.05);
}

}  // namespace
}  // namespace ewa::test
