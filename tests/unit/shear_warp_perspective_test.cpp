// Perspective shear-warp: the factorization's warp is the camera's projection, each ray's
// opacity is that of its own length, the near plane, and run-length encoding and threads.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/shear_warp.h"
#include "shear_warp_test_volumes.h"

namespace ewa {
namespace {

using namespace swtest;

Camera perspectiveCamera(const glm::dvec3& position, const glm::dvec3& focal) {
  Camera cam;
  cam.position = position;
  cam.focalPoint = focal;
  cam.viewUp = glm::dvec3(0, 0, 1);
  cam.viewAngleDeg = 40.0;
  return cam;
}

// Voxels of the drawn slices land, through the warp, where the camera projects them; the ratio
// of each ray is its world length between slices over the slice spacing; the intermediate image
// has about the picture's resolution, up to kMaxIntermediatePerVoxel pixels a voxel.
TEST(ShearWarpPerspective, WarpOfScaledSlicesIsTheCameraProjection) {
  const std::array<int64_t, 3> dims{20, 30, 12};
  const glm::dvec3 spacing(1.0, 0.5, 2.0), origin(-3.0, 4.0, 1.0);
  const glm::dvec3 centre = origin + glm::dvec3(9.5, 7.25, 11.0);
  for (const glm::dvec3 offset : {glm::dvec3(6.0, 4.0, 40.0), glm::dvec3(-30.0, 6.0, 8.0),
                                  glm::dvec3(5.0, -35.0, -12.0), glm::dvec3(2.0, 3.0, -28.0)}) {
    const Camera cam = perspectiveCamera(centre + offset, centre);
    const ShearWarpFactorization f = factorizeView(cam, dims, spacing, origin, 300, 200);
    ASSERT_TRUE(f.perspective);
    ASSERT_FALSE(f.perspectiveAsParallel);
    EXPECT_EQ(f.sliceCount, f.depth);  // the eye is outside the volume
    const Projection proj = cam.projection(300, 200);
    for (const glm::ivec3 voxel :
         {glm::ivec3(0, 0, 0), glm::ivec3(19, 29, 11), glm::ivec3(7, 3, 9), glm::ivec3(19, 0, 5)}) {
      const glm::dvec3 world = origin + glm::dvec3(voxel) * spacing;
      const glm::dvec3 q(cam.viewMatrix() * glm::dvec4(world, 1.0));
      const glm::dvec2 expected = proj.principal + glm::dvec2(q.x, q.y) * (proj.focalPixels / -q.z);
      const int k = voxel[f.principal];
      const double s = f.scale(k);
      EXPECT_GT(s, 0.0);
      const glm::dvec3 uv(s * voxel[f.axisI] + f.offsetI(k), s * voxel[f.axisJ] + f.offsetJ(k),
                          1.0);
      if (expected.x >= 0 && expected.y >= 0 && expected.x <= 300 && expected.y <= 200) {
        // In the picture: inside the intermediate image, which covers only what is seen.
        EXPECT_GE(uv.x, 0.0);
        EXPECT_GE(uv.y, 0.0);
        EXPECT_LE(uv.x, f.imageWidth - 1);
        EXPECT_LE(uv.y, f.imageHeight - 1);
      }
      const glm::dvec3 h = f.warp * uv;
      EXPECT_NEAR(h.x / h.z, expected.x, 1e-9);
      EXPECT_NEAR(h.y / h.z, expected.y, 1e-9);
      const glm::dvec3 back = f.inverseWarp * glm::dvec3(expected, 1.0);
      EXPECT_GT(back.z, 0.0);
      EXPECT_NEAR(back.x / back.z, uv.x, 1e-9);
      EXPECT_NEAR(back.y / back.z, uv.y, 1e-9);
      // From the eye to the voxel: its world length per slice, over the slice spacing.
      const double slices = std::abs(k - f.eye.z);
      EXPECT_NEAR(f.rayRatio(uv.x, uv.y),
                  glm::length(world - cam.position) / (slices * f.sliceSpacing), 1e-9);
    }
    // At least a voxel an intermediate pixel on the front slice; this picture is finer than
    // kMaxIntermediatePerVoxel pixels a voxel at the focal point, which its slice gets.
    EXPECT_GE(f.scale(f.sliceAt(0)), 1.0 - 1e-12);
    glm::dvec3 focal = (cam.focalPoint - origin) / spacing;
    focal = glm::dvec3(focal[f.axisI], focal[f.axisJ], focal[f.principal]);
    EXPECT_NEAR(f.referenceDistance / std::abs(focal.z - f.eye.z), kMaxIntermediatePerVoxel, 1e-9);
    // A picture a tenth as wide: an intermediate pixel at the middle about a pixel of it (more
    // where the slices are seen obliquely, or the front slice asks for more).
    const ShearWarpFactorization small = factorizeView(cam, dims, spacing, origin, 30, 20);
    const glm::dvec2 middle = cam.projection(30, 20).principal;
    const glm::dvec3 h0 = small.inverseWarp * glm::dvec3(middle, 1.0);
    for (const glm::dvec2 step : {glm::dvec2(1, 0), glm::dvec2(0, 1)}) {
      const glm::dvec3 h1 = small.inverseWarp * glm::dvec3(middle + step, 1.0);
      const double moved = glm::length(glm::dvec2(h1) / h1.z - glm::dvec2(h0) / h0.z);
      EXPECT_GE(moved, 0.99);
      EXPECT_LE(moved, 6.0);  // finer across the narrower voxel side (0.5 against 1), obliquely
    }
    // Front to back: the front slice is the one nearest the eye.
    const int front = f.sliceAt(0), back = f.sliceAt(f.sliceCount - 1);
    EXPECT_LT(std::abs(front - f.eye.z), std::abs(back - f.eye.z));
  }
}

// An eye inside the volume draws the slices a voxel or more in front of it; one looking away
// from the volume draws nothing; neither gives NaNs.
TEST(ShearWarpPerspective, TheNearPlaneIsOneVoxelInFrontOfTheEye) {
  const Volume v = makeVolume(32, ScalarType::UInt8, blob);
  const std::array<int64_t, 3> dims = v.dims();
  Camera inside = perspectiveCamera(glm::dvec3(15.2, 14.1, 10.4), glm::dvec3(15.0, 14.0, 30.0));
  const ShearWarpFactorization f = factorizeView(inside, dims, v.spacing(), v.origin(), 64, 64);
  ASSERT_TRUE(f.perspective);
  EXPECT_EQ(f.principal, 2);
  EXPECT_TRUE(f.increasing);
  EXPECT_EQ(f.frontSlice, 12);  // ceil(10.4 + 1)
  EXPECT_EQ(f.sliceCount, 20);
  for (bool pre : {false, true}) {
    ShearWarpSettings s;
    s.preintegrated = pre;
    const FloatImage img = renderOnce(v, blobTf(), inside, s);
    for (float x : img.values) ASSERT_TRUE(std::isfinite(x));
    EXPECT_GT(totalAlpha(img), 100.0) << pre;
    const Camera away = perspectiveCamera(glm::dvec3(15.0, 14.0, -10.0), glm::dvec3(15, 14, -30));
    EXPECT_EQ(totalAlpha(renderOnce(v, blobTf(), away, s)), 0.0) << pre;
  }
}

// A homogeneous medium seen close up: every ray through the front and back faces has the
// opacity of its own length, 1 - exp(-tau n ratio) for n samples d' = ratio d apart, however
// obliquely it runs; without correction, that of n samples d apart.
TEST(ShearWarpPerspective, EachRayHasTheOpacityOfItsLength) {
  const double tau = 0.025;
  TransferFunction tf;
  tf.opacity = {{0.0, 1.0 - std::exp(-tau)}};
  tf.color = {{0.0, {1.0, 1.0, 1.0}}};
  const Volume v = makeVolume(32, ScalarType::UInt8, [](int, int, int) { return 255.0; });
  Camera cam = perspectiveCamera(glm::dvec3(16.0, 14.0, -20.0), glm::dvec3(15.5, 15.5, 15.5));
  cam.viewAngleDeg = 60.0;  // rays 14 degrees off the axis, crossing both faces
  const int size = 65;
  const Projection proj = cam.projection(size, size);
  const glm::dmat3 toWorld = glm::transpose(cam.rotation());
  for (bool pre : {false, true})
    for (bool correct : {false, true}) {
      ShearWarpSettings s;
      s.preintegrated = pre;
      s.opacityCorrection = correct;
      const FloatImage img = renderOnce(v, tf, cam, s, size);
      for (const glm::ivec2 pixel :
           {glm::ivec2(32, 32), glm::ivec2(22, 42), glm::ivec2(42, 22), glm::ivec2(22, 22)}) {
        const glm::dvec2 q = (glm::dvec2(pixel) + 0.5 - proj.principal) / proj.focalPixels;
        const glm::dvec3 dir = toWorld * glm::dvec3(q, -1.0);
        const double ratio = glm::length(dir) / std::abs(dir.z);
        if (pixel.x != 32) {
          EXPECT_GT(ratio, 1.02);  // far enough off the axis to tell (0.01 in alpha)
        }
        const double length = (pre ? 31.0 : 32.0) * (correct ? ratio : 1.0);
        const int row = size - 1 - pixel.y;
        EXPECT_NEAR(img.at(pixel.x, row, 3), 1.0 - std::exp(-tau * length), 2e-3)
            << "preintegrated " << pre << " correction " << correct << " pixel " << pixel.x << ","
            << pixel.y;
        EXPECT_NEAR(img.at(pixel.x, row, 0), img.at(pixel.x, row, 3), 1e-5);
      }
    }
}

TEST(ShearWarpPerspective, RunLengthEncodingAndThreadsDoNotChangeThePicture) {
  const Volume v = makeVolume(32, ScalarType::UInt8, blob);
  for (const glm::dvec3 eye :
       {glm::dvec3(30.0, 25.0, 60.0), glm::dvec3(-25.0, 10.0, 20.0), glm::dvec3(8, -30, -20)})
    expectRunsAndThreadsKeepThePicture(v, perspectiveCamera(eye, glm::dvec3(15.5)));
}

// Cameras anywhere: far and near, inside the volume, on a slice's plane, looking away, at
// grazing angles and wide, with a crop box and a clipping plane: every picture finite, its
// opacity within [0, 1] and its colour premultiplied (no channel above the opacity).
TEST(ShearWarpPerspective, AnyCameraGivesAFinitePicture) {
  const Volume v = makeVolume(16, ScalarType::UInt8,
                              [](int i, int j, int k) { return blob(2 * i, 2 * j, 2 * k); });
  uint32_t seed = 12345;
  auto next = [&] {  // a small LCG: the same cameras on every machine
    seed = seed * 1664525u + 1013904223u;
    return double(seed >> 8) / double(1u << 24);
  };
  ClipRegion clip;
  clip.cropEnabled = true;
  clip.cropMin = glm::dvec3(2.0, -5.0, 3.0);
  clip.cropMax = glm::dvec3(13.0, 20.0, 12.5);
  clip.planes.push_back({glm::dvec3(7.5), glm::normalize(glm::dvec3(1.0, 2.0, -1.0)), true});
  for (int n = 0; n < 60; ++n) {
    Camera cam;
    const double far = n % 3 == 0 ? 40.0 : n % 3 == 1 ? 12.0 : 4.0;
    cam.position = glm::dvec3(7.5) + far * (2.0 * glm::dvec3(next(), next(), next()) - 1.0);
    if (n % 10 == 4) cam.position.z = 6.0;  // on a slice's plane
    cam.focalPoint = glm::dvec3(7.5) + 8.0 * (2.0 * glm::dvec3(next(), next(), next()) - 1.0);
    cam.viewUp = glm::dvec3(0.0, 0.0, 1.0);
    cam.viewAngleDeg = 10.0 + 100.0 * next();
    if (!cam.valid()) continue;
    ShearWarpSettings s;
    s.preintegrated = n % 2 == 1;
    s.lookup = n % 4 == 3 ? TableLookup::Bilinear : TableLookup::Nearest;
    s.opacityCorrection = n % 5 != 0;
    ShearWarp sw;
    sw.setVolume(v);
    sw.setTransferFunction(blobTf());
    sw.render(cam, s, 24, 20, n % 3 == 2 ? clip : ClipRegion{});
    const FloatImage& img = sw.image();
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const float a = img.at(x, y, 3);
        ASSERT_TRUE(std::isfinite(a)) << n;
        ASSERT_GE(a, 0.0f) << n;
        ASSERT_LE(a, 1.0f + 1e-5f) << n;
        for (int c = 0; c < 3; ++c) {
          ASSERT_TRUE(std::isfinite(img.at(x, y, c))) << n;
          ASSERT_LE(img.at(x, y, c), a + 1e-4f) << n << " channel " << c;
        }
      }
  }
}

}  // namespace
}  // namespace ewa
