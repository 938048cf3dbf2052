// Data and view edge cases render cleanly: tiny and flat volumes, constant and NaN/infinite
// data, transparent and opaque transfer functions, the eye inside or right at the voxels, and
// extreme zoom. Every case checks that no NaN or infinity reaches the optical depth or image.
#include <cmath>
#include <cstring>
#include <limits>

#include "gl/gl_error.h"
#include "image_compare.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class EdgeCases : public RenderFixture {
 protected:
  static constexpr int kW = 24, kH = 20;

  // X-ray pass: the summed optical depth, checked finite and non-negative; returns its sum.
  double xraySum(const Camera& cam, RenderSettings settings = {}) {
    settings.mode = RenderMode::XRay;
    renderer()->render(cam, settings, kW, kH);
    const std::vector<float> depth = renderer()->readOpticalDepth();
    EXPECT_EQ(depth.size(), size_t(kW) * kH);
    double sum = 0.0;
    for (float d : depth) {
      EXPECT_TRUE(std::isfinite(d) && d >= 0.0f) << "optical depth " << d;
      if (!std::isfinite(d)) break;
      sum += d;
    }
    return sum;
  }

  // Composite pass over a blue background.
  Image8 composite(const Camera& cam, RenderSettings settings = {}) {
    settings.mode = RenderMode::Composite;
    settings.background = {0.0, 0.0, 1.0};
    renderer()->render(cam, settings, kW, kH);
    return renderer()->readImage();
  }

  // Both passes of `vol` with `tf`; returns the composite image.
  Image8 renderBoth(const Volume& vol, const TransferFunction& tf, const Camera& cam,
                    double* depthSum = nullptr) {
    renderer()->setVolume(vol);
    renderer()->setTransferFunction(tf);
    const double sum = xraySum(cam);
    if (depthSum) *depthSum = sum;
    return composite(cam);
  }

  static Camera lookAt(glm::dvec3 eye, glm::dvec3 at, double angle = 30.0) {
    Camera cam;
    cam.position = eye;
    cam.focalPoint = at;
    cam.viewAngleDeg = angle;
    return cam;
  }

  static int pixel(const Image8& img, int x, int y, int c) {
    return img.pixels[(size_t(y) * img.width + x) * 3 + c];
  }
  // Pixels whose red channel is lit (the volume is white over a blue background).
  static int litPixels(const Image8& img) {
    int n = 0;
    for (size_t p = 0; p < img.pixels.size(); p += 3) n += img.pixels[p] > 0;
    return n;
  }
};

TransferFunction rampTf(double lo, double hi, double alpha) {
  TransferFunction tf;
  tf.opacity = {{lo, 0.0}, {hi, alpha}};
  tf.color = {{lo, glm::dvec3(1.0)}, {hi, glm::dvec3(1.0)}};
  return tf;
}

TEST_F(EdgeCases, SingleVoxelVolume) {
  const Volume one = makeVolume(1, 1, 1, glm::dvec3(1.0), [](int, int, int) { return true; });
  double sum = 0.0;
  const Image8 img = renderBoth(one, whiteTf(0.9, 1.0), lookAt({0, 0, 6}, {0, 0, 0}), &sum);
  EXPECT_EQ(renderer()->stats().splatsDrawn, 1u);
  EXPECT_GT(sum, 0.0);
  EXPECT_GT(pixel(img, kW / 2, kH / 2, 0), 20);  // the splat is in the middle
  EXPECT_EQ(pixel(img, 0, 0, 0), 0);             // and only there
  EXPECT_EQ(pixel(img, 0, 0, 2), 255);
}

TEST_F(EdgeCases, OneVoxelThickVolumesSeenFromEverySide) {
  const std::array<int, 3> shapes[] = {{8, 8, 1}, {8, 1, 8}, {1, 8, 8}};
  const glm::dvec3 dirs[] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {1, 1, 1}};
  for (const auto& s : shapes) {
    const Volume flat =
        makeVolume(s[0], s[1], s[2], glm::dvec3(1.0), [](int, int, int) { return true; });
    const glm::dvec3 centre = (flat.boundsMin() + flat.boundsMax()) * 0.5;
    for (const glm::dvec3& d : dirs) {
      // Edge-on views see the sheet as a line; others as a square. Either is drawn.
      double sum = 0.0;
      const Image8 img =
          renderBoth(flat, whiteTf(0.5, 1.0), lookAt(centre + 20.0 * d, centre), &sum);
      EXPECT_GT(sum, 0.0) << s[0] << "x" << s[1] << "x" << s[2];
      EXPECT_GT(litPixels(img), 0);
    }
  }
}

TEST_F(EdgeCases, ConstantVolumeUsesItsOneValue) {
  std::vector<uint8_t> bytes(6 * 6 * 6, 77);
  const Volume flat({6, 6, 6}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, bytes);
  EXPECT_EQ(flat.minValue(), 77.0);
  EXPECT_EQ(flat.maxValue(), 77.0);
  const Camera cam = lookAt({2.5, 2.5, 30}, {2.5, 2.5, 2.5});
  // Opaque at 77: drawn; transparent at 77: nothing.
  double sum = 0.0;
  Image8 img = renderBoth(flat, rampTf(0.0, 77.0, 0.6), cam, &sum);
  EXPECT_EQ(renderer()->stats().splatsTotal, 216u);
  EXPECT_GT(pixel(img, kW / 2, kH / 2, 0), 100);
  img = renderBoth(flat, rampTf(77.0, 200.0, 0.6), cam, &sum);
  EXPECT_EQ(sum, 0.0);
  EXPECT_EQ(litPixels(img), 0);
}

TEST_F(EdgeCases, NanAndInfinityVoxelsAreTransparentAndDoNotPoisonTheRange) {
  // A ball of value 10 in a float volume; outside it alternating NaN, +inf, -inf and 0.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const auto ball = [](int i, int j, int k) {
    return (i - 4) * (i - 4) + (j - 4) * (j - 4) + (k - 4) * (k - 4) <= 9;
  };
  const Volume poisoned = floatVolume(9, [&](int i, int j, int k) {
    if (ball(i, j, k)) return 10.0f;
    const int n = (i + j + k) % 4;
    return n == 0 ? nan : n == 1 ? inf : n == 2 ? -inf : 0.0f;
  });
  const Volume clean =
      floatVolume(9, [&](int i, int j, int k) { return ball(i, j, k) ? 10.0f : 0.0f; });
  EXPECT_EQ(poisoned.minValue(), 0.0);
  EXPECT_EQ(poisoned.maxValue(), 10.0);
  // Non-finite voxels are left out of the histogram: only bin 0 (the zeros) loses them.
  int nonFinite = 0;
  for (int64_t n = 0; n < poisoned.voxelCount(); ++n)
    nonFinite += !std::isfinite(poisoned.valueAt(n));
  ASSERT_GT(nonFinite, 300);
  std::vector<uint64_t> expected = clean.histogram();
  expected[0] -= uint64_t(nonFinite);
  EXPECT_EQ(poisoned.histogram(), expected);
  // Opaque even at 0 and beyond the range: NaN/inf voxels would show if they were splatted.
  TransferFunction tf = rampTf(0.0, 10.0, 0.4);
  tf.opacity = {{0.0, 0.2}, {10.0, 0.4}};
  const Camera cam = lookAt({4, 4, 30}, {4, 4, 4});
  double poisonedSum = 0.0, cleanSum = 0.0;
  const Image8 a = renderBoth(poisoned, tf, cam, &poisonedSum);
  const size_t poisonedSplats = renderer()->stats().splatsTotal;
  const Image8 b = renderBoth(clean, tf, cam, &cleanSum);
  // Only the 0-valued quarter and the ball are splatted in the poisoned volume.
  EXPECT_LT(poisonedSplats, renderer()->stats().splatsTotal);
  EXPECT_GT(poisonedSum, 0.0);
  EXPECT_LT(poisonedSum, cleanSum);
  // With the value-0 voxels transparent, the two volumes give the same picture pre-classified
  // (post-classified, the clean volume's 0-valued margin voxels enter the slab means).
  renderer()->setTransferFunction(rampTf(0.0, 10.0, 0.4));
  renderer()->setPartition(PartitionMode::Cpu);  // equal to the bit: the same order of sums
  renderer()->setVolume(poisoned);
  const Image8 c = composite(cam, paperSettings());
  renderer()->setVolume(clean);
  const Image8 d = composite(cam, paperSettings());
  EXPECT_EQ(c.pixels, d.pixels);
  EXPECT_GT(litPixels(c), 10);
  (void)a;
  (void)b;
}

TEST_F(EdgeCases, AllTransparentAndAllOpaqueTransferFunctions) {
  const Volume cube = makeVolume(8, 8, 8, glm::dvec3(1.0), [](int i, int, int) { return i > 1; });
  const Camera cam = lookAt({3.5, 3.5, 40}, {3.5, 3.5, 3.5});
  TransferFunction none;
  none.opacity = {{0.0, 0.0}, {255.0, 0.0}};
  double sum = -1.0;
  Image8 img = renderBoth(cube, none, cam, &sum);
  EXPECT_EQ(sum, 0.0);
  EXPECT_EQ(litPixels(img), 0);
  EXPECT_EQ(pixel(img, kW / 2, kH / 2, 2), 255);
  // Alpha 1 everywhere (clamped to a finite extinction): opaque white where the cube is.
  TransferFunction all;
  all.opacity = {{0.0, 1.0}, {255.0, 1.0}};
  img = renderBoth(cube, all, cam, &sum);
  EXPECT_TRUE(std::isfinite(sum));
  EXPECT_EQ(renderer()->stats().splatsTotal, 512u);
  EXPECT_GE(pixel(img, kW / 2, kH / 2, 0), 250);
  EXPECT_GE(pixel(img, kW / 2, kH / 2, 2), 250);
  EXPECT_GE(pixel(img, kW / 2, kH / 2, 1), 250);
}

TEST_F(EdgeCases, TinyOpacityUnitDistanceGivesOpaqueNotNan) {
  // tau = 13.8 / 1e-300 overflows float: found by the tf_json fuzzer (infinite tau made the
  // slab colour inf / inf = NaN, drawn black). Now capped: the cube is opaque white.
  const Volume cube = makeVolume(6, 6, 6, glm::dvec3(1.0), [](int, int, int) { return true; });
  TransferFunction tf = whiteTf(1.0, 1.0);
  tf.opacityUnitDistance = 1e-300;
  double sum = 0.0;
  const Image8 img = renderBoth(cube, tf, lookAt({2.5, 2.5, 30}, {2.5, 2.5, 2.5}), &sum);
  EXPECT_TRUE(std::isfinite(sum));
  EXPECT_GE(pixel(img, kW / 2, kH / 2, 0), 250);
  EXPECT_GE(pixel(img, kW / 2, kH / 2, 1), 250);
}

TEST_F(EdgeCases, EyeInsideTheVolumeAndNearPlaneThroughVoxels) {
  const Volume cube = makeVolume(12, 12, 12, glm::dvec3(1.0), [](int, int, int) { return true; });
  const TransferFunction tf = whiteTf(0.2, 1.0);
  // The eye at the centre, at a voxel centre, and a hair in front of a voxel layer.
  for (const glm::dvec3 eye : {glm::dvec3(5.5, 5.5, 5.5), glm::dvec3(5, 5, 5),
                               glm::dvec3(5.2, 5.3, 5.0001), glm::dvec3(5.5, 5.5, 11.01)}) {
    double sum = 0.0;
    const Image8 img =
        renderBoth(cube, tf, lookAt(eye, eye + glm::dvec3(0.1, 0.05, -1.0), 60), &sum);
    EXPECT_GT(sum, 0.0);
    EXPECT_LT(renderer()->stats().splatsDrawn, renderer()->stats().splatsTotal);  // some culled
    EXPECT_GT(litPixels(img), kW * kH / 2) << "surrounded by voxels, the view is filled";
  }
}

TEST_F(EdgeCases, ExtremeZoomInAndOut) {
  const Volume cube = makeVolume(6, 6, 6, glm::dvec3(1.0), [](int, int, int) { return true; });
  const TransferFunction tf = whiteTf(0.3, 1.0);
  const glm::dvec3 c(2.5);
  // Far away: the whole volume is below a pixel; the EWA low-pass keeps it one blob of the
  // same optical mass as from nearby (tested loosely: the kernels overlap the image border
  // from nearby).
  double near = 0.0, far = 0.0, tiny = 0.0;
  renderBoth(cube, tf, lookAt(c + glm::dvec3(0, 0, 60), c), &near);
  Image8 img = renderBoth(cube, tf, lookAt(c + glm::dvec3(0, 0, 1e6), c), &far);
  EXPECT_GT(far, 0.0);
  EXPECT_LE(litPixels(img), 16);
  img = renderBoth(cube, tf, lookAt(c + glm::dvec3(0, 0, 60), c, 1e-3), &tiny);
  EXPECT_TRUE(std::isfinite(tiny));  // a view angle of 0.001 degrees: one voxel fills the view
  EXPECT_EQ(litPixels(img), kW * kH);
  img = renderBoth(cube, tf, lookAt(c + glm::dvec3(0, 0, 60), c, 179.0), &far);
  EXPECT_GT(far, 0.0);
  // Orthographic, far and near.
  Camera ortho = lookAt(c + glm::dvec3(0, 0, 1e5), c);
  ortho.orthographic = true;
  img = renderBoth(cube, tf, ortho, &far);
  EXPECT_GT(far, 0.0);
  ortho.position = c + glm::dvec3(0, 0, 1e-3);
  img = renderBoth(cube, tf, ortho, &far);
  EXPECT_TRUE(std::isfinite(far));
  EXPECT_GT(near, 0.0);
}

TEST_F(EdgeCases, TooManyVisibleVoxelsIsAClearError) {
  const Volume cube = makeVolume(8, 8, 8, glm::dvec3(1.0), [](int, int, int) { return true; });
  renderer()->setVolume(cube);
  renderer()->setTransferFunction(whiteTf(0.3, 1.0));
  renderer()->setMaxSplats(100);
  try {
    renderer()->render(lookAt({3.5, 3.5, 30}, {3.5, 3.5, 3.5}), {}, kW, kH);
    ADD_FAILURE() << "no error for 512 splats over a limit of 100";
  } catch (const ::ewa::gl::GlError& e) {
    EXPECT_NE(std::string(e.what()).find("more than 100 visible voxels"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("GL_MAX_TEXTURE_BUFFER_SIZE"), std::string::npos)
        << e.what();
  }
  renderer()->setMaxSplats(SIZE_MAX);
  // The renderer is still usable afterwards.
  EXPECT_GT(xraySum(lookAt({3.5, 3.5, 30}, {3.5, 3.5, 3.5})), 0.0);
}

TEST_F(EdgeCases, ImageLargerThanTheGlLimitIsAClearError) {
  GLint maxTexture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
  const Volume one = makeVolume(1, 1, 1, glm::dvec3(1.0), [](int, int, int) { return true; });
  renderer()->setVolume(one);
  renderer()->setTransferFunction(whiteTf(0.3, 1.0));
  try {
    renderer()->render(lookAt({0, 0, 5}, {0, 0, 0}), {}, maxTexture + 1, 4);
    ADD_FAILURE() << "no error for an image wider than GL_MAX_TEXTURE_SIZE";
  } catch (const ::ewa::gl::GlError& e) {
    EXPECT_NE(std::string(e.what()).find("GL_MAX_TEXTURE_SIZE"), std::string::npos) << e.what();
  }
  EXPECT_GT(xraySum(lookAt({0, 0, 5}, {0, 0, 0})), 0.0);
}

}  // namespace
}  // namespace ewa::test
