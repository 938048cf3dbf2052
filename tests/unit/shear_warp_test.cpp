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

// The pixel `cam` projects the world point to.
glm::dvec2 projected(const Camera& cam, const Projection& proj, const glm::dvec3& world) {
  const glm::dvec3 q(cam.viewMatrix() * glm::dvec4(world, 1.0));
  return proj.principal + glm::dvec2(q.x, q.y) * proj.pixelsPerUnit;
}

// The voxel lies inside the intermediate image, where the warp takes it to `pixel` and back.
void expectVoxelWarpsTo(const ShearWarpFactorization& f, const glm::ivec3& voxel,
                        const glm::dvec2& pixel) {
  const int k = voxel[f.principal];
  const glm::dvec3 uv(f.scale(k) * voxel[f.axisI] + f.offsetI(k),
                      f.scale(k) * voxel[f.axisJ] + f.offsetJ(k), 1.0);
  EXPECT_GE(uv.x, 0.0);
  EXPECT_GE(uv.y, 0.0);
  EXPECT_LE(uv.x, f.imageWidth);
  EXPECT_LE(uv.y, f.imageHeight);
  const glm::dvec3 warped = f.warp * uv;
  EXPECT_NEAR(warped.x, pixel.x, 1e-9);
  EXPECT_NEAR(warped.y, pixel.y, 1e-9);
  const glm::dvec3 back = f.inverseWarp * warped;
  EXPECT_NEAR(back.x, uv.x, 1e-9);
}

TEST(ShearWarpFactorization, WarpOfShearedSlicesIsTheCameraProjection) {
  const std::array<int64_t, 3> dims{20, 30, 12};
  const glm::dvec3 spacing(1.0, 0.5, 2.0), origin(-3.0, 4.0, 1.0);
  for (const glm::dvec3 from : {glm::dvec3(0.3, 0.2, 1.0), glm::dvec3(-1.0, 0.4, 0.3),
                                glm::dvec3(0.2, -1.0, -0.6), glm::dvec3(0.1, 0.1, -1.0)}) {
    Camera cam;
    cam.orthographic = true;
    cam.frame(origin, origin + glm::dvec3(19, 29 * 0.5, 11 * 2.0), from, glm::dvec3(0, 0, 1), 1.5);
    for (const double most : {1.0, kMaxIntermediatePerVoxel, 3.5}) {
      const ShearWarpFactorization f = factorizeView(cam, dims, spacing, origin, 300, 200, most);
      // Principal axis: largest component of the direction in voxel units.
      const glm::dvec3 step = cam.direction() / spacing;
      EXPECT_GE(std::abs(step[f.principal]), std::abs(step[(f.principal + 1) % 3]));
      EXPECT_GE(std::abs(step[f.principal]), std::abs(step[(f.principal + 2) % 3]));
      // Magnified by the picture's pixels across the wider voxel side, 1 to `most`.
      const Projection proj = cam.projection(300, 200);
      const double across = std::max(spacing[f.axisI], spacing[f.axisJ]);
      EXPECT_DOUBLE_EQ(f.magnification, std::clamp(proj.pixelsPerUnit * across, 1.0, most));
      EXPECT_EQ(f.resampled(), f.magnification != 1.0);
      EXPECT_GT(proj.pixelsPerUnit * across, 2.0);  // so that every `most` is reached
      EXPECT_LE(std::abs(f.shearI), f.magnification);
      EXPECT_LE(std::abs(f.shearJ), f.magnification);
      EXPECT_NEAR(f.sampleRatio * std::abs(cam.direction()[f.principal]), 1.0, 1e-12);
      for (const glm::ivec3 voxel :
           {glm::ivec3(0, 0, 0), glm::ivec3(19, 29, 11), glm::ivec3(7, 3, 9)}) {
        expectVoxelWarpsTo(f, voxel, projected(cam, proj, origin + glm::dvec3(voxel) * spacing));
      }
      // Front to back: slice 0 in front when the ray moves towards larger k.
      const double first = glm::dot(cam.direction(), origin + glm::dvec3(0.0));
      glm::dvec3 lastIdx(0.0);
      lastIdx[f.principal] = f.depth - 1;
      const double last = glm::dot(cam.direction(), origin + lastIdx * spacing);
      EXPECT_EQ(f.increasing, first < last);
    }
  }
}

TEST(ShearWarpFactorization, CloseUpsCompositeOnlyThePicturesRays) {
  const std::array<int64_t, 3> dims{60, 50, 40};
  const glm::dvec3 spacing(1.0, 1.2, 0.8), origin(2.0, -1.0, 3.0);
  Camera cam;
  cam.orthographic = true;
  cam.frame(origin, origin + glm::dvec3(59, 49 * 1.2, 39 * 0.8), glm::dvec3(0.4, -0.3, 1.0),
            glm::dvec3(0, 1, 0), 1.0);
  cam.viewAngleDeg /= 6.0;  // a sixth of the volume's height across the picture
  for (const double most : {1.0, kMaxIntermediatePerVoxel}) {
    const ShearWarpFactorization f = factorizeView(cam, dims, spacing, origin, 120, 90, most);
    EXPECT_LT(f.imageWidth, 0.5 * f.magnification * dims[f.axisI]);
    EXPECT_LT(f.imageHeight, 0.5 * f.magnification * dims[f.axisJ]);
    const Projection proj = cam.projection(120, 90);
    int seen = 0;
    for (int k = 0; k < 40; k += 3)
      for (int j = 0; j < 50; j += 2)
        for (int i = 0; i < 60; i += 2) {
          const glm::dvec2 pixel = projected(cam, proj, origin + glm::dvec3(i, j, k) * spacing);
          if (pixel.x < 0.0 || pixel.y < 0.0 || pixel.x > 120.0 || pixel.y > 90.0) continue;
          ++seen;
          expectVoxelWarpsTo(f, glm::ivec3(i, j, k), pixel);
        }
    EXPECT_GT(seen, 100);
  }
}

TEST(ShearWarp, BufferSliceVariantsGiveIdenticalImages) {
  const Volume v = makeVolume(32, ScalarType::UInt8, blob);
  const Camera cam = obliqueCamera(v, glm::dvec3(0.5, 0.35, 1.0));
  for (TableLookup lookup : {TableLookup::Nearest, TableLookup::Bilinear}) {
    ShearWarpSettings s;
    s.preintegrated = true;
    s.lookup = lookup;
    s.intermediateScale = 1.0;  // Lacroute's loop; magnified views always buffer by pixel
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
       {glm::dvec3(0.5, 0.35, 1.0), glm::dvec3(-1.0, 0.2, 0.6), glm::dvec3(0.3, -1.0, -0.4)}) {
    Camera cam = obliqueCamera(v, from);
    expectRunsAndThreadsKeepThePicture(v, cam);
    cam.viewAngleDeg /= 3.0;  // close up: runs reach past the intermediate image's edges
    expectRunsAndThreadsKeepThePicture(v, cam);
  }
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
    for (bool correct : {false, true})
      for (int size : {65, 200}) {
        ShearWarpSettings s;
        s.preintegrated = pre;
        s.opacityCorrection = correct;
        s.intermediateScale = size == 65 ? 1.0 : 2.0;  // Lacroute's loop, and magnified
        const FloatImage img = renderOnce(v, tf, cam, s, size);
        // Standard: 32 samples of length d'; pre-integrated: 31 slabs between them.
        const double length = (pre ? 31.0 : 32.0) * (correct ? ratio : 1.0);
        const int c = size / 2;
        EXPECT_NEAR(img.at(c, c, 3), 1.0 - std::exp(-tau * length), 2e-3)
            << "preintegrated " << pre << " correction " << correct << " size " << size;
        EXPECT_NEAR(img.at(c, c, 0), img.at(c, c, 3), 1e-5);  // white, premultiplied
      }
}

// Pixels of an opaque ball's silhouette that are neither clear nor opaque, and its area, drawn
// close up (about 5 pixels a voxel) with at most `scale` intermediate pixels a voxel.
glm::dvec2 ballEdge(double scale) {
  const Volume v = makeVolume(32, ScalarType::UInt8, [](int i, int j, int k) {
    return glm::length(glm::dvec3(i, j, k) - glm::dvec3(15.5, 15.2, 15.8)) < 10.0 ? 200.0 : 0.0;
  });
  TransferFunction tf;
  tf.opacity = {{99.0, 0.0}, {101.0, 1.0}};
  tf.color = {{0.0, {1.0, 1.0, 1.0}}};
  tf.opacityUnitDistance = 0.05;
  ShearWarpSettings s;
  s.intermediateScale = scale;
  const FloatImage img = renderOnce(v, tf, obliqueCamera(v, glm::dvec3(0.3, 0.2, 1.0)), s, 256);
  double partial = 0.0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) partial += img.at(x, y, 3) > 0.1 && img.at(x, y, 3) < 0.9;
  return {partial, totalAlpha(img)};
}

TEST(ShearWarp, MagnifiedParallelViewsHaveSharperEdges) {
  // One intermediate pixel a voxel: the warp spreads each edge over a voxel's 5 pixels; two
  // and four: over half and a quarter of that. The silhouette's area stays.
  const glm::dvec2 one = ballEdge(1.0), two = ballEdge(2.0), four = ballEdge(4.0);
  std::printf("ball edge: partial pixels %.0f, %.0f, %.0f; area %.0f, %.0f, %.0f\n", one.x, two.x,
              four.x, one.y, two.y, four.y);
  EXPECT_GT(one.x, 500.0);
  EXPECT_LT(two.x, 0.65 * one.x);
  EXPECT_LT(four.x, 0.65 * two.x);
  EXPECT_NEAR(two.y / one.y, 1.0, 0.02);
  EXPECT_NEAR(four.y / one.y, 1.0, 0.02);
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
