// CPU shear-warp: factorization, buffer-slice variants, run-length encoding, threads, scalar
// types, homogeneous medium, and the thin-peak iso-surface with and without pre-integration.
#include "core/shear_warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <glm/geometric.hpp>

#include "shear_warp_test_volumes.h"

namespace ewa {
namespace {

using namespace swtest;

TEST(ShearWarpFactorization, WarpOfShearedSlicesIsTheCameraProjection) {
  const std::array<int64_t, 3> dims{20, 30, 12};
  const glm::dvec3 spacing(1.0, 0.5, 2.0), origin(-3.0, 4.0, 1.0);
  for (const glm::dvec3 from : {glm::dvec3(0.3, 0.2, 1.0), glm::dvec3(-1.0, 0.4, 0.3),
                                glm::dvec3(0.2, -1.0, -0.6), glm::dvec3(0.1, 0.1, -1.0)}) {
    Camera cam;
    cam.orthographic = true;
    cam.frame(origin, origin + glm::dvec3(19, 29 * 0.5, 11 * 2.0), from, glm::dvec3(0, 0, 1), 1.5);
    const ShearWarpFactorization f = factorizeView(cam, dims, spacing, origin, 300, 200);
    // Principal axis: largest component of the direction in voxel units.
    const glm::dvec3 step = cam.direction() / spacing;
    EXPECT_GE(std::abs(step[f.principal]), std::abs(step[(f.principal + 1) % 3]));
    EXPECT_GE(std::abs(step[f.principal]), std::abs(step[(f.principal + 2) % 3]));
    EXPECT_LE(std::abs(f.shearI), 1.0);
    EXPECT_LE(std::abs(f.shearJ), 1.0);
    EXPECT_NEAR(f.sampleRatio * std::abs(cam.direction()[f.principal]), 1.0, 1e-12);
    const Projection proj = cam.projection(300, 200);
    for (const glm::ivec3 voxel :
         {glm::ivec3(0, 0, 0), glm::ivec3(19, 29, 11), glm::ivec3(7, 3, 9)}) {
      const glm::dvec3 world = origin + glm::dvec3(voxel) * spacing;
      const glm::dvec3 q(cam.viewMatrix() * glm::dvec4(world, 1.0));
      const glm::dvec2 expected = proj.principal + glm::dvec2(q.x, q.y) * proj.pixelsPerUnit;
      const int k = voxel[f.principal];
      const glm::dvec3 uv(voxel[f.axisI] + f.offsetI(k), voxel[f.axisJ] + f.offsetJ(k), 1.0);
      EXPECT_GE(uv.x, 0.0);
      EXPECT_GE(uv.y, 0.0);
      EXPECT_LE(uv.x, f.imageWidth);
      EXPECT_LE(uv.y, f.imageHeight);
      const glm::dvec3 pixel = f.warp * uv;
      EXPECT_NEAR(pixel.x, expected.x, 1e-9);
      EXPECT_NEAR(pixel.y, expected.y, 1e-9);
      const glm::dvec3 back = f.inverseWarp * pixel;
      EXPECT_NEAR(back.x, uv.x, 1e-9);
    }
    // Front to back: slice 0 in front when the ray moves towards larger k.
    const double first = glm::dot(cam.direction(), origin + glm::dvec3(0.0));
    glm::dvec3 lastIdx(0.0);
    lastIdx[f.principal] = f.depth - 1;
    const double last = glm::dot(cam.direction(), origin + lastIdx * spacing);
    EXPECT_EQ(f.increasing, first < last);
  }
}

TEST(ShearWarp, BufferSliceVariantsGiveIdenticalImages) {
  const Volume v = makeVolume(32, ScalarType::UInt8, blob);
  const Camera cam = obliqueCamera(v, glm::dvec3(0.5, 0.35, 1.0));
  for (TableLookup lookup : {TableLookup::Nearest, TableLookup::Bilinear}) {
    ShearWarpSettings s;
    s.preintegrated = true;
    s.lookup = lookup;
    s.buffers = BufferSlices::Slice;
    const FloatImage sb = renderOnce(v, blobTf(), cam, s);
    s.buffers = BufferSlices::Image;
    const FloatImage ib = renderOnce(v, blobTf(), cam, s);
    EXPECT_GT(totalAlpha(sb), 100.0);
    EXPECT_EQ(sb.values, ib.values) << tableLookupName(lookup);
  }
}

TEST(ShearWarp, RunLengthEncodingAndThreadsDoNotChangeThePicture) {
  const Volume v = makeVolume(32, ScalarType::UInt8, blob);
  for (const glm::dvec3 from :
       {glm::dvec3(0.5, 0.35, 1.0), glm::dvec3(-1.0, 0.2, 0.6), glm::dvec3(0.3, -1.0, -0.4)})
    expectRunsAndThreadsKeepThePicture(v, obliqueCamera(v, from));
}

TEST(ShearWarp, EveryScalarTypeMapsThroughTheTransferFunctionRange) {
  const ShearWarpSettings s;
  const Volume ref = makeVolume(32, ScalarType::UInt8, blob);
  const Camera cam = obliqueCamera(ref, glm::dvec3(0.4, 0.3, 1.0));
  const FloatImage expected = renderOnce(ref, blobTf(), cam, s);
  EXPECT_GT(totalAlpha(expected), 100.0);
  struct Case {
    ScalarType type;
    double scale, offset;
  };
  for (const Case c : {Case{ScalarType::Int16, 10.0, -1000.0}, Case{ScalarType::UInt16, 300.0, 7.0},
                       Case{ScalarType::Float32, 0.01, -0.5}}) {
    const Volume v = makeVolume(32, c.type, blob, c.scale, c.offset);
    const FloatImage img = renderOnce(v, blobTf(c.scale, c.offset), cam, s);
    EXPECT_LT(maxDifference(img, expected), 1e-4) << scalarName(c.type);
  }
}

TEST(ShearWarp, HomogeneousMediumHasTheOpacityOfItsThickness) {
  const double tau = 0.025;
  TransferFunction tf;
  tf.opacity = {{0.0, 1.0 - std::exp(-tau)}};
  tf.color = {{0.0, {1.0, 1.0, 1.0}}};
  const Volume v = makeVolume(32, ScalarType::UInt8, [](int, int, int) { return 255.0; });
  const Camera cam = obliqueCamera(v, glm::dvec3(0.3, 0.2, 1.0));
  const double ratio = 1.0 / std::abs(cam.direction().z);
  for (bool pre : {false, true})
    for (bool correct : {false, true}) {
      ShearWarpSettings s;
      s.preintegrated = pre;
      s.opacityCorrection = correct;
      const FloatImage img = renderOnce(v, tf, cam, s, 65);
      // Standard: 32 samples of length d'; pre-integrated: 31 slabs between them.
      const double length = (pre ? 31.0 : 32.0) * (correct ? ratio : 1.0);
      EXPECT_NEAR(img.at(32, 32, 3), 1.0 - std::exp(-tau * length), 2e-3)
          << "preintegrated " << pre << " correction " << correct;
      EXPECT_NEAR(img.at(32, 32, 0), img.at(32, 32, 3), 1e-5);  // white, premultiplied
    }
}

// Distance from the centre of a 40^3 grid; the transfer function is a thin opaque shell at 12.
struct ThinPeakMeasure {
  double covered;  // fraction of the disk inside 0.75 R with alpha > 0.9
  double spread;   // standard deviation of alpha there
};

ThinPeakMeasure measureThinPeak(bool preintegrated) {
  const Volume v = makeVolume(40, ScalarType::Float32, [](int i, int j, int k) {
    return glm::length(glm::dvec3(i, j, k) - glm::dvec3(19.5));
  });
  TransferFunction tf;
  tf.opacity = {{11.7, 0.0}, {11.9, 1.0}, {12.1, 1.0}, {12.3, 0.0}};
  tf.color = {{0.0, {1.0, 0.8, 0.5}}};
  tf.opacityUnitDistance = 0.1;  // opaque where the ray crosses the shell
  const Camera cam = obliqueCamera(v, glm::dvec3(0.15, 0.1, 1.0));
  ShearWarpSettings s;
  s.preintegrated = preintegrated;
  const int size = 96;
  const FloatImage img = renderOnce(v, tf, cam, s, size);
  const double radius = 12.0 * cam.projection(size, size).pixelsPerUnit;
  double n = 0, covered = 0, sum = 0, sum2 = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      if (std::hypot(x + 0.5 - size / 2.0, y + 0.5 - size / 2.0) > 0.75 * radius) continue;
      const double a = img.at(x, y, 3);
      n += 1;
      covered += a > 0.9;
      sum += a;
      sum2 += a * a;
    }
  return {covered / n, std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)))};
}

TEST(ShearWarp, ThinPeakIsAClosedSurfaceOnlyWithPreintegration) {
  const ThinPeakMeasure pre = measureThinPeak(true);
  const ThinPeakMeasure standard = measureThinPeak(false);
  std::printf(
      "thin peak: pre-integrated covered %.3f spread %.3f; standard covered %.3f spread %.3f\n",
      pre.covered, pre.spread, standard.covered, standard.spread);
  EXPECT_GT(pre.covered, 0.99);
  EXPECT_LT(pre.spread, 0.02);
  EXPECT_LT(standard.covered, 0.8);
  EXPECT_GT(standard.spread, 0.1);
}

TEST(ShearWarp, DegenerateInputGivesAnEmptyPictureNotNaNs) {
  ShearWarp sw;
  const ShearWarpSettings s;
  Camera cam;
  cam.orthographic = true;
  sw.render(cam, s, 8, 8);  // no volume
  EXPECT_EQ(totalAlpha(sw.image()), 0.0);
  const Volume one = makeVolume(1, ScalarType::UInt8, [](int, int, int) { return 5.0; });
  sw.setVolume(one);
  sw.setTransferFunction(blobTf());
  for (bool pre : {false, true}) {
    ShearWarpSettings p;
    p.preintegrated = pre;
    sw.render(cam, p, 8, 8);
    for (float x : sw.image().values) EXPECT_TRUE(std::isfinite(x));
  }
  // NaN voxels in a float volume stay finite in the picture.
  const Volume nan = makeVolume(16, ScalarType::Float32,
                                [](int i, int, int) { return i % 3 ? 150.0 : std::nan(""); });
  sw.setVolume(nan);
  sw.render(obliqueCamera(nan, glm::dvec3(0.2, 0.3, 1.0)), s, 16, 16);
  for (float x : sw.image().values) EXPECT_TRUE(std::isfinite(x));
}

}  // namespace
}  // namespace ewa
