// LodRenderer: full quality equals the plain renderer; coarse levels are smaller, cheaper
// images of nearly the same picture (the downsampled kernels are correspondingly wider).
#include "render/lod_renderer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/synthetic_volume.h"
#include "gl/shader_library.h"
#include "image_compare.h"
#include "io/png_io.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class LodRendererTest : public RenderFixture {};

// Mean absolute difference (0..255) of b against a, b scaled to a's size (nearest pixel).
double meanDifference(const Image8& a, const Image8& b) {
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const int bx = x * b.width / a.width, by = y * b.height / a.height;
      for (int c = 0; c < 3; ++c)
        sum += std::abs(int(a.pixels[size_t(y * a.width + x) * 3 + c]) -
                        int(b.pixels[size_t(by * b.width + bx) * 3 + c]));
    }
  return sum / (double(a.width) * a.height * 3);
}

double meanValue(const Image8& a) {
  double sum = 0.0;
  for (uint8_t v : a.pixels) sum += v;
  return sum / double(a.pixels.size());
}

TEST_F(LodRendererTest, LevelsShrinkImageAndSplatsButKeepThePicture) {
  const SyntheticVolume s = makeSyntheticVolume("sphere:32");
  const gl::ShaderLibrary shaders;
  LodRenderer lod([&shaders] { return std::make_unique<SplatRenderer>(shaders); });
  lod.setVolume(s.volume, buildLodVolumes(s.volume));
  lod.setTransferFunction(*s.transferFunction);
  Camera cam;
  cam.frame(s.volume.boundsMin(), s.volume.boundsMax(), {0.3, 0.4, 1.0}, {0, 1, 0}, 1.0);
  const RenderSettings settings;

  // Level 0 is the plain renderer's picture.
  renderer()->setVolume(s.volume);
  renderer()->setTransferFunction(*s.transferFunction);
  renderer()->render(cam, settings, 64, 64);
  const Image8 plain = renderer()->readImage();
  lod.render(0, cam, settings, 64, 64);
  const Image8 full = lod.last().readImage();
  EXPECT_EQ(meanDifference(plain, full), 0.0);
  const size_t fullSplats = lod.last().stats().splatsTotal;
  ASSERT_GT(meanValue(full), 5.0);  // something to compare
  writePng(testOutputDir() + "/lod_level0.png", full);

  for (int level = 1; level < LodPolicy::kLevelCount; ++level) {
    const LodLevel l = LodPolicy::level(level);
    lod.render(level, cam, settings, 64, 64);
    EXPECT_EQ(lod.imageWidth(), 64 / l.imageDivisor) << level;
    const Image8 coarse = lod.last().readImage();
    EXPECT_EQ(coarse.width, 64 / l.imageDivisor);
    // Roughly splats / factor^3 (the sphere's shell rounds differently).
    const double ratio = double(lod.last().stats().splatsTotal) / double(fullSplats);
    const double f3 = std::pow(l.volumeFactor, 3);
    EXPECT_LT(ratio, 2.0 / f3) << level;
    EXPECT_GT(ratio, 0.3 / f3) << level;
    // Same opacity overall (the mass is kept), a blurrier picture: within a few percent of
    // the full-quality brightness and a modest mean difference per pixel.
    EXPECT_NEAR(meanValue(coarse), meanValue(full), 0.15 * meanValue(full)) << level;
    // Compared pixel by pixel after nearest upscaling, so 16x16 images (divisor 4) are blocky,
    // and the last levels hold this 32^3 sphere in 4^3 voxels: a wider blob; at divisor 8 the
    // image is 8x8, so only a blank or misplaced picture fails (the brightness check above holds).
    const double allowed = l.imageDivisor >= 8 ? 0.9 : l.imageDivisor >= 4 ? 0.7 : 0.25;
    EXPECT_LT(meanDifference(full, coarse), allowed * meanValue(full)) << level;
    writePng(testOutputDir() + "/lod_level" + std::to_string(level) + ".png", coarse);
  }
  EXPECT_GT(lod.gpuBytes(), fullSplats * 8);
}

}  // namespace
}  // namespace ewa::test
