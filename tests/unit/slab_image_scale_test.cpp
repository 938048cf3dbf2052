// SlabImageScale: which slabs may be splatted into coarser images, how a coarser image maps the
// picture (its border texel, its rectangles), and that a footprint summed on it and read back
// bilinearly stays near the one summed at full resolution.
#include "core/slab_image_scale.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

namespace ewa {
namespace {

KernelReach perspectiveReach(double focal) {
  Projection proj;
  proj.focalPixels = focal;
  proj.width = proj.height = 512;
  return kernelReach(proj, FilterMode::Ewa, 5.0, glm::dvec3(1.0), 0.7, 1.0);
}

TEST(SlabImageScale, FollowsTheSmallestFootprintOfTheSlab) {
  const KernelReach reach = perspectiveReach(1000.0);
  // sigma 0.7 world units: 7 pixels at depth 100, 0.7 at depth 1000.
  EXPECT_NEAR(minFootprintSigma(reach, 0.7, 100.0), 7.0, 1e-12);
  EXPECT_NEAR(minFootprintSigma(reach, 0.7, 1000.0), 0.7, 1e-12);
  // 2 texels on an image s times coarser, s in quarter steps: sigma >= 2.5 pixels for 1.25,
  // >= 3 for 1.5, >= 4 for 2, >= 8 for 4.
  EXPECT_EQ(slabImageScale(reach, 0.7, 1000.0), 1.0);
  EXPECT_EQ(slabImageScale(reach, 0.7, 0.7 * 1000.0 / 2.49), 1.0);
  EXPECT_EQ(slabImageScale(reach, 0.7, 0.7 * 1000.0 / 2.51), 1.25);
  EXPECT_EQ(slabImageScale(reach, 0.7, 0.7 * 1000.0 / 3.3), 1.5);  // the default window's view
  EXPECT_EQ(slabImageScale(reach, 0.7, 0.7 * 1000.0 / 3.99), 1.75);
  EXPECT_EQ(slabImageScale(reach, 0.7, 0.7 * 1000.0 / 4.01), 2.0);
  EXPECT_EQ(slabImageScale(reach, 0.7, 0.7 * 1000.0 / 7.99), 3.75);
  EXPECT_EQ(slabImageScale(reach, 0.7, 0.7 * 1000.0 / 8.01), 4.0);
  EXPECT_EQ(slabImageScale(reach, 0.7, 1.0), kMaxSlabImageScale);  // never coarser than 4
  // Every scale keeps the smallest footprint kMinSigmaTexels texels wide on its image.
  for (double sigma = 0.5; sigma < 12.0; sigma += 0.01) {
    const double s = slabImageScale(reach, 0.7, 0.7 * 1000.0 / sigma);
    if (s > 1.0) {
      EXPECT_GE(sigma / s, kMinSigmaTexels - 1e-9) << sigma;
    }
    EXPECT_EQ(std::fmod(s, kSlabImageScaleStep), 0.0) << sigma;
  }
  EXPECT_EQ(slabImageScale(reach, 0.7, 0.0), kMaxSlabImageScale);  // at the eye: infinitely wide
  // Orthographic: the same at every depth.
  KernelReach ortho = reach;
  ortho.orthographic = true;
  ortho.pixelsPerUnit = 3.5;  // sigma 2.45 pixels
  EXPECT_EQ(slabImageScale(ortho, 0.7, 1.0), 1.0);
  EXPECT_EQ(slabImageScale(ortho, 0.7, 1e6), 1.0);
  ortho.pixelsPerUnit = 6.0;  // 4.2
  EXPECT_EQ(slabImageScale(ortho, 0.7, 1.0), 2.0);
  EXPECT_EQ(slabImageScale(ortho, 0.7, 1e6), 2.0);
}

TEST(SlabImageScale, CoarserProjectionHasABorderTexel) {
  Projection p;
  p.focalPixels = 700.0;
  p.pixelsPerUnit = 3.0;
  p.principal = {192.0, 150.5};
  p.width = 384;
  p.height = 301;
  const Projection s = scaledProjection(p, 2);
  EXPECT_EQ(s.focalPixels, 350.0);
  EXPECT_EQ(s.pixelsPerUnit, 1.5);
  EXPECT_EQ(s.principal.x, 97.0);  // 192 / 2 + 1
  EXPECT_EQ(s.principal.y, 76.25);
  EXPECT_EQ(s.width, 194);  // 192 texels and one each side
  EXPECT_EQ(s.height, 153);
  // A point projected by p lands at its scaledCoordinate under s.
  const double x = 37.25;
  EXPECT_DOUBLE_EQ(s.principal.x + (x - p.principal.x) / 2.0, scaledCoordinate(x, 2));
  EXPECT_EQ(scaledProjection(p, 1).width, 384);
  EXPECT_EQ(scaledCoordinate(x, 1), x);
  // Every texel a bilinear read of a picture pixel centre takes lies inside the image.
  for (double scale : {1.25, 1.5, 1.75, 2.0, 3.25, 4.0}) {
    const Projection q = scaledProjection(p, scale);
    EXPECT_EQ(q.width, int(std::ceil(384.0 / scale)) + 2) << scale;
    for (int px : {0, 1, p.width - 2, p.width - 1}) {
      const double u = scaledCoordinate(px + 0.5, scale) - 0.5;
      EXPECT_GE(std::floor(u), 0.0) << scale << " " << px;
      EXPECT_LT(std::floor(u) + 1.0, double(q.width)) << scale << " " << px;
    }
  }
}

TEST(SlabImageScale, RectHoldsEveryTexelItsPixelsRead) {
  const PixelRect r{13, 7, 101, 64};
  EXPECT_EQ(scaledRect(r, 1).x0, 13);
  EXPECT_TRUE(scaledRect(PixelRect{}, 2).empty());
  for (double scale : {1.25, 1.5, 2.0, 2.75, 4.0}) {
    const PixelRect s = scaledRect(r, scale);
    for (int x = r.x0; x < r.x1; ++x) {
      const double u = scaledCoordinate(x + 0.5, scale) - 0.5;
      EXPECT_GE(int(std::floor(u)), s.x0);
      EXPECT_LT(int(std::floor(u)) + 1, s.x1);
    }
    for (int y = r.y0; y < r.y1; ++y) {
      const double v = scaledCoordinate(y + 0.5, scale) - 0.5;
      EXPECT_GE(int(std::floor(v)), s.y0);
      EXPECT_LT(int(std::floor(v)) + 1, s.y1);
    }
    // No more than a texel of margin beyond what is read.
    EXPECT_LE(s.x1 - s.x0, int(double(r.x1 - r.x0) / scale) + 3);
  }
}

// The marks' blit maps each picture coordinate where scaledCoordinate does (a blit maps its
// rectangles' ends linearly), covers the picture, and reads no texel past the coarser image's
// own (ceil(width / scale) + 2 wide) beyond what lies outside the picture.
TEST(SlabImageScale, CoarseBlitMapsPixelsAsTheBilinearReadDoes) {
  for (int width : {16, 97, 1024}) {
    for (double scale = 1.25; scale <= kMaxSlabImageScale; scale += kSlabImageScaleStep) {
      const BlitRects r = coarseToPictureBlit(width, 768, scale);
      EXPECT_EQ(r.destination.x0, 0);
      EXPECT_GE(r.destination.x1, width);
      EXPECT_GE(r.destination.y1, 768);
      const double ratio =
          double(r.source.x1 - r.source.x0) / (r.destination.x1 - r.destination.x0);
      EXPECT_NEAR(ratio, 1.0 / scale, 1e-12) << scale;
      EXPECT_NEAR(double(r.source.y1 - r.source.y0) / (r.destination.y1 - r.destination.y0),
                  1.0 / scale, 1e-12);
      for (double x : {0.5, 7.5, double(width) - 0.5})
        EXPECT_NEAR(r.source.x0 + (x - r.destination.x0) * ratio, scaledCoordinate(x, scale), 1e-9)
            << width << " " << scale;
      // The picture's last pixel reads a texel of the coarser image.
      const double last = scaledCoordinate(width - 0.5, scale);
      Projection picture;
      picture.width = width;
      picture.height = 768;
      EXPECT_LT(last, scaledProjection(picture, scale).width);
    }
  }
}

// The rule's premise, in one dimension: a Gaussian at least kMinSigmaTexels texels wide,
// sampled at texel centres and read back linearly between them, is within 1/(8 sigma^2) of its
// peak everywhere (3.1% at 2 texels; an isolated kernel, the worst case: the sums of
// neighbouring kernels are smoother), and its samples sum to its integral within 0.1%.
TEST(SlabImageScale, LinearReadBackOfAWideEnoughGaussian) {
  const double sigma = kMinSigmaTexels;
  double worst = 0.0;
  for (double centre = 0.0; centre < 1.0; centre += 0.125) {
    std::vector<double> texel(40);
    double sum = 0.0;
    for (size_t i = 0; i < texel.size(); ++i) {
      const double d = (double(i) + 0.5 - 20.0 - centre) / sigma;
      texel[i] = std::exp(-0.5 * d * d);
      sum += texel[i];
    }
    EXPECT_NEAR(sum, sigma * std::sqrt(2.0 * M_PI), 1e-3 * sum);
    for (double x = 10.5; x < 29.5; x += 0.05) {
      const size_t i = size_t(std::floor(x - 0.5));
      const double t = x - 0.5 - double(i);
      const double read = (1.0 - t) * texel[i] + t * texel[i + 1];
      const double d = (x - 20.0 - centre) / sigma;
      worst = std::max(worst, std::abs(read - std::exp(-0.5 * d * d)));
    }
  }
  EXPECT_LT(worst, 1.0 / (8.0 * sigma * sigma) + 1e-3);
  EXPECT_GT(worst, 0.02);  // not exact: the rule's margin is real
}

// Splatting the kernel narrower by kBilinearReadVariance makes up, on average over where the
// pixels fall between texels, for the blur of the read-back: the read-back of the narrowed
// samples is nearer the true Gaussian (worst error about two thirds, mean square about half).
TEST(SlabImageScale, NarrowerKernelsMakeUpForTheReadBacksBlur) {
  const double sigma = kMinSigmaTexels;
  const auto errors = [&](double variance) {
    double worst = 0.0, squares = 0.0;
    int n = 0;
    for (double centre = 0.0; centre < 1.0; centre += 0.0625) {
      std::vector<double> texel(40);
      for (size_t i = 0; i < texel.size(); ++i) {
        const double d = double(i) + 0.5 - 20.0 - centre;
        texel[i] = std::exp(-0.5 * d * d / variance) / std::sqrt(variance);
      }
      for (double x = 10.5; x < 29.5; x += 0.05) {
        const size_t i = size_t(std::floor(x - 0.5));
        const double t = x - 0.5 - double(i);
        const double read = (1.0 - t) * texel[i] + t * texel[i + 1];
        const double d = x - 20.0 - centre;
        const double error = read - std::exp(-0.5 * d * d / (sigma * sigma)) / sigma;
        worst = std::max(worst, std::abs(error));
        squares += error * error;
        ++n;
      }
    }
    return std::make_pair(worst, squares / n);
  };
  const auto plain = errors(sigma * sigma);
  const auto narrowed = errors(sigma * sigma - kBilinearReadVariance);
  EXPECT_LT(narrowed.first, 0.75 * plain.first);
  EXPECT_LT(narrowed.second, 0.5 * plain.second);
  // Narrowing by twice as much overshoots: the variance is the tent's, not a guess.
  const auto twice = errors(sigma * sigma - 2.0 * kBilinearReadVariance);
  EXPECT_GT(twice.second, narrowed.second);
}

}  // namespace
}  // namespace ewa
