// Volumes with a direction matrix are drawn in world space by both renderers: a flipped copy
// with its direction negated, and a rotated direction, give the pictures their world geometry
// calls for.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "core/image_metrics.h"
#include "core/volume_orientation.h"
#include "image_compare.h"
#include "io/image_convert.h"
#include "render/shear_warp_renderer.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

constexpr int kNx = 24, kNy = 18, kNz = 14;
const glm::dvec3 kSpacing(1.0, 1.5, 2.0);
const glm::dvec3 kOrigin(3.0, -4.0, 5.0);

// An asymmetric object (a block with a bar and a ball off to one side), values 0..200.
uint8_t asymmetricValue(int i, int j, int k) {
  const bool block = i >= 3 && i < 12 && j >= 2 && j < 10 && k >= 2 && k < 9;
  const bool bar = i >= 12 && i < 22 && j >= 6 && j < 9 && k >= 5 && k < 8;
  const int di = i - 18, dj = j - 13, dk = k - 10;
  const bool ball = di * di + dj * dj + dk * dk <= 10;
  return uint8_t(block ? 120 : bar ? 200 : ball ? 160 : 0);
}

// The grid with data axes reversed where `flip` says (so that the voxel that was at index i is
// at n-1-i), as raw bytes.
std::vector<uint8_t> gridBytes(glm::bvec3 flip) {
  std::vector<uint8_t> bytes(size_t(kNx) * kNy * kNz);
  for (int k = 0; k < kNz; ++k)
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i)
        bytes[size_t(i + kNx * (j + kNy * k))] = asymmetricValue(
            flip.x ? kNx - 1 - i : i, flip.y ? kNy - 1 - j : j, flip.z ? kNz - 1 - k : k);
  return bytes;
}

Volume plainVolume() {
  return Volume({kNx, kNy, kNz}, kSpacing, kOrigin, ScalarType::UInt8,
                gridBytes({false, false, false}));
}

// The same world object stored with the axes in `flip` reversed: origin at the far end of each
// reversed axis and that column of the direction negated. A single reversal is a reflection:
// it goes through makeRotation as loaders do.
Volume flippedVolume(glm::bvec3 flip) {
  std::vector<uint8_t> bytes = gridBytes(flip);
  OrientedGrid g;
  g.dims = {kNx, kNy, kNz};
  g.bytes = &bytes;
  g.spacing = kSpacing;
  g.origin = kOrigin;
  const glm::dvec3 n(kNx - 1, kNy - 1, kNz - 1);
  for (int a = 0; a < 3; ++a) {
    if (!flip[a]) continue;
    g.origin[a] += n[a] * kSpacing[a];
    g.direction[a] = -g.direction[a];
  }
  makeRotation(g);
  Volume v({kNx, kNy, kNz}, kSpacing, g.origin, ScalarType::UInt8, std::move(bytes));
  v.setDirection(g.direction, false);
  return v;
}

TransferFunction objectTf() {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {100.0, 0.0}, {120.0, 0.3}, {200.0, 0.6}};
  tf.color = {{120.0, {0.9, 0.4, 0.2}}, {160.0, {0.3, 0.9, 0.3}}, {200.0, {0.3, 0.5, 1.0}}};
  tf.opacityUnitDistance = 2.0;
  return tf;
}

Camera obliqueCamera(const Volume& v) {
  Camera c;
  c.frame(v.worldBoundsMin(), v.worldBoundsMax(), glm::dvec3(0.5, -0.8, 0.6), glm::dvec3(0, 0, 1),
          1.0);
  return c;
}

class OrientationRender : public RenderFixture {
 protected:
  // The picture of `v` under `cam` from the splat renderer and from shear-warp.
  std::array<FloatImage, 2> pictures(const Volume& v, const Camera& cam, const std::string& name) {
    RenderSettings settings;
    settings.background = glm::dvec3(0.05);
    renderer()->setVolume(v);
    renderer()->setTransferFunction(objectTf());
    renderer()->render(cam, settings, 96, 96);
    const Image8 splat = renderer()->readImage();
    ShearWarpRenderer sw;
    sw.setVolume(v);
    sw.setTransferFunction(objectTf());
    sw.render(cam, settings, 96, 96);
    const Image8 shear = sw.readImage();
    if (std::getenv("EWA_KEEP_IMAGES")) {
      writePng(testOutputDir() + "/orientation_" + name + "_splat.png", splat);
      writePng(testOutputDir() + "/orientation_" + name + "_shearwarp.png", shear);
    }
    return {toFloatImage(splat), toFloatImage(shear)};
  }
};

TEST_F(OrientationRender, FlippedAxesWithNegatedDirectionsDrawTheSamePicture) {
  const Volume plain = plainVolume();
  const Camera cam = obliqueCamera(plain);
  const auto expected = pictures(plain, cam, "plain");
  for (const glm::bvec3 flip : {glm::bvec3(true, false, false), glm::bvec3(false, true, true),
                                glm::bvec3(true, true, true)}) {
    const Volume flipped = flippedVolume(flip);
    const std::string name =
        std::to_string(flip.x) + std::to_string(flip.y) + std::to_string(flip.z);
    const auto got = pictures(flipped, cam, "flip" + name);
    // Were the direction ignored, the flipped data would look different.
    Volume ignored({kNx, kNy, kNz}, kSpacing, kOrigin, ScalarType::UInt8, gridBytes(flip));
    const auto wrong = pictures(ignored, cam, "ignored" + name);
    for (int r = 0; r < 2; ++r) {
      const double rmse = rootMeanSquareError(got[size_t(r)], expected[size_t(r)]);
      const double wrongRmse = rootMeanSquareError(wrong[size_t(r)], expected[size_t(r)]);
      std::printf("%s flip %s: RMSE %.4f (direction ignored: %.4f)\n", r ? "shear-warp" : "splat",
                  name.c_str(), rmse, wrongRmse);
      // Shear-warp samples each slice where the shear puts it, and a reversed slice order
      // moves those points by a fraction of a voxel: the same object, resampled a little apart.
      EXPECT_LT(rmse, r ? 0.03 : 0.005) << (r ? "shear-warp" : "splat") << " flip " << name;
      EXPECT_GT(wrongRmse, 0.06) << (r ? "shear-warp" : "splat") << " flip " << name;
    }
  }
}

TEST_F(OrientationRender, RotatedDirectionLooksLikeTheCounterRotatedCamera) {
  // D turns data x into world y and data y into world -x (90 degrees about z), origin 0.
  std::vector<uint8_t> bytes = gridBytes({false, false, false});
  Volume rotated({kNx, kNy, kNz}, kSpacing, glm::dvec3(0.0), ScalarType::UInt8, bytes);
  rotated.setDirection(glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1)),
                       true);
  Camera world;
  world.position = {20, -60, 30};
  world.focalPoint = {-10, 15, 12};
  world.viewUp = {0, 0, 1};
  // The same camera turned back by hand: (x, y, z) -> (y, -x, z).
  Camera local = world;
  local.position = {-60, -20, 30};
  local.focalPoint = {15, 10, 12};
  const Volume plain({kNx, kNy, kNz}, kSpacing, glm::dvec3(0.0), ScalarType::UInt8, bytes);
  const auto got = pictures(rotated, world, "rotated");
  const auto expected = pictures(plain, local, "rotated_reference");
  const auto unrotated = pictures(plain, world, "unrotated");
  for (int r = 0; r < 2; ++r) {
    const double rmse = rootMeanSquareError(got[size_t(r)], expected[size_t(r)]);
    const double wrongRmse = rootMeanSquareError(got[size_t(r)], unrotated[size_t(r)]);
    std::printf("%s rotated: RMSE %.4f (unrotated: %.4f)\n", r ? "shear-warp" : "splat", rmse,
                wrongRmse);
    EXPECT_LT(rmse, 0.005) << (r ? "shear-warp" : "splat");
    EXPECT_GT(wrongRmse, 0.06) << (r ? "shear-warp" : "splat");
  }
}

}  // namespace
}  // namespace ewa::test
