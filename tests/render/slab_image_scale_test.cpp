// Slab images as coarse as the kernels allow (src/core/slab_image_scale.h) and the splat
// viewport's guard band: magnified pictures keep their edges, and coarser slab images draw the
// picture full resolution draws, within a few levels, where they are used at all.
#include <algorithm>
#include <cmath>
#include <glm/trigonometric.hpp>

#include "image_compare.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class SlabImageScaleRender : public RenderFixture {};

// A smooth, bumpy 16^3 field: values vary inside, so post-classification has edges to keep.
Volume bumpyVolume() {
  return floatVolume(16, [](int i, int j, int k) {
    const glm::dvec3 p = glm::dvec3(i, j, k) - glm::dvec3(7.5);
    return float(std::max(0.0, 9.0 - glm::length(p)) *
                 (1.0 + 0.4 * std::sin(0.9 * i) * std::cos(0.7 * j + 0.5 * k)));
  });
}

TransferFunction rampTf() {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {2.0, 0.0}, {5.0, 0.35}, {9.0, 0.8}, {13.0, 0.9}};
  tf.color = {{0.0, glm::dvec3(0.2, 0.4, 1.0)},
              {6.0, glm::dvec3(1.0, 0.7, 0.3)},
              {13.0, glm::dvec3(1.0, 1.0, 0.9)}};
  tf.opacityUnitDistance = 1.0;
  return tf;
}

int maxChannelDifference(const Image8& a, const Image8& b) {
  int worst = 0;
  for (size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i)
    worst = std::max(worst, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
  return worst;
}

// The central w x h pixels of `img`.
Image8 centre(const Image8& img, int w, int h) {
  Image8 out;
  out.width = w;
  out.height = h;
  out.channels = 3;
  const int x0 = (img.width - w) / 2, y0 = (img.height - h) / 2;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w * 3; ++x)
      out.pixels.push_back(img.pixels[(size_t(y0 + y) * img.width + x0) * 3 + x]);
  return out;
}

// A magnified view cut by the picture's edges is the middle of a wider picture with the same
// focal length: splats centred just outside the picture still draw their part inside. Without
// the guard band GL dropped those points whole and the edges came out as a ragged dark frame.
TEST_F(SlabImageScaleRender, EdgesOfAMagnifiedPictureMatchAWiderOne) {
  const Volume vol = bumpyVolume();
  renderer()->setVolume(vol);
  renderer()->setTransferFunction(rampTf());
  Camera cam;
  cam.focalPoint = glm::dvec3(7.5);
  cam.position = cam.focalPoint + glm::dvec3(6.0, -9.0, 14.0);  // the ball overfills the view
  cam.viewUp = {0.0, 0.0, 1.0};
  cam.viewAngleDeg = 30.0;
  const int narrow = 64, wide = 96;
  for (bool post : {false, true}) {
    RenderSettings settings = rasterSettings();  // slab images
    settings.coarseSlabs = false;
    if (!post) settings.classification.mode = ClassificationMode::Pre;
    renderer()->render(cam, settings, narrow, narrow);
    const Image8 small = renderer()->readImage();
    Camera wider = cam;
    const double focal = 0.5 * narrow / std::tan(glm::radians(0.5 * cam.viewAngleDeg));
    wider.viewAngleDeg = glm::degrees(2.0 * std::atan(0.5 * wide / focal));
    renderer()->render(wider, settings, wide, wide);
    const Image8 middle = centre(renderer()->readImage(), narrow, narrow);
    // The edge pixels are covered (the volume fills the view) and agree.
    double edge = 0.0;
    for (int x = 0; x < narrow; ++x) edge += small.pixels[size_t(x) * 3];
    EXPECT_GT(edge / narrow, 20.0) << "the bottom row must be covered";
    EXPECT_LE(maxChannelDifference(small, middle), 3) << (post ? "post" : "pre");
  }
}

struct Magnified {
  Image8 coarse, full;
  RenderStats coarseStats, fullStats;
};

Magnified renderBoth(SplatRenderer& r, RenderSettings settings, int size) {
  r.setPartition(PartitionMode::Cpu);  // the same order of sums in both: equal to the bit
  const Volume vol = bumpyVolume();
  r.setVolume(vol);
  r.setTransferFunction(rampTf());
  Camera cam;
  cam.focalPoint = glm::dvec3(7.5);
  cam.position = cam.focalPoint + glm::dvec3(16.0, -22.0, 30.0);
  cam.viewUp = {0.0, 0.0, 1.0};
  Magnified m;
  // One pass a slab in both frames: auto tries one and two on hardware GL, and the two passes'
  // culling rounds a level apart there in float slab images (PassHalf's test).
  settings.slabPasses = 1;
  settings.coarseSlabs = true;
  r.render(cam, settings, size, size);
  m.coarse = r.readImage();
  m.coarseStats = r.stats();
  settings.coarseSlabs = false;
  r.render(cam, settings, size, size);
  m.full = r.readImage();
  m.fullStats = r.stats();
  return m;
}

// About 7 pixels a voxel, kernels 5 pixels wide: the near slabs go to half resolution, the
// picture stays within a few levels of full resolution in every unshaded classification (and
// pre-classified shading, whose slabs sum light, not values): 2 levels at most, 0.16-0.3 on
// average. Drawn with the picture's low-pass filter left at a texel (4 pixels^2), 0.7-10% of
// the pixels were off by more than 2.
TEST_F(SlabImageScaleRender, CoarserSlabImagesKeepThePicture) {
  struct Case {
    const char* name;
    ClassificationMode mode;
    bool preintegrated, shading;
  };
  const Case cases[] = {{"post, pre-integrated", ClassificationMode::Post, true, false},
                        {"post, slab means", ClassificationMode::Post, false, false},
                        {"pre", ClassificationMode::Pre, true, false},
                        {"pre, shaded", ClassificationMode::Pre, true, true}};
  for (const Case& c : cases) {
    RenderSettings settings = rasterSettings();  // slab images
    settings.classification.mode = c.mode;
    settings.slabPreintegration = c.preintegrated;
    settings.lighting.enabled = c.shading;
    const Magnified m = renderBoth(*renderer(), settings, 128);
    EXPECT_GT(m.coarseStats.slabsCoarse, m.coarseStats.slabsDrawn / 3) << c.name;
    EXPECT_EQ(m.fullStats.slabsCoarse, 0u) << c.name;
    const ImageDifference d = compareCovered(m.coarse, m.full, Rgb8{0, 0, 0}, 2);
    ASSERT_GT(d.covered, 5000u) << c.name;
    EXPECT_LT(d.mean, 0.5) << c.name;
    EXPECT_LT(d.badFraction, 0.003) << c.name;
    EXPECT_LE(maxChannelDifference(m.coarse, m.full), 3) << c.name;
    if (HasFailure()) {
      writePng(testOutputDir() + "/slab_scale_coarse.png", m.coarse);
      writePng(testOutputDir() + "/slab_scale_full.png", m.full);
    }
  }
}

// Shaded post-classification takes its normals from differences of the slab's values, which
// the bilinear read-back bends: it keeps full resolution; so do minified views.
TEST_F(SlabImageScaleRender, ShadedPostAndSmallFootprintsStayFull) {
  RenderSettings shaded = rasterSettings();  // slab images
  shaded.lighting.enabled = true;
  const Magnified m = renderBoth(*renderer(), shaded, 128);
  EXPECT_EQ(m.coarseStats.slabsCoarse, 0u);
  EXPECT_EQ(m.coarse.pixels, m.full.pixels);
  const Magnified small = renderBoth(*renderer(), rasterSettings(), 24);  // a pixel a voxel
  EXPECT_EQ(small.coarseStats.slabsCoarse, 0u);
  EXPECT_EQ(small.coarse.pixels, small.full.pixels);
}

}  // namespace
}  // namespace ewa::test
