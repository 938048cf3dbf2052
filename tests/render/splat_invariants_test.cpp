// The invariants of ../shared/DESIGN.md on the GPU: shader = C++ reference, mass, homogeneous
// medium, degenerate views.
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "render_fixture.h"

namespace ewa::test {
namespace {

class SplatInvariants : public RenderFixture {};

struct SplatCase {
  FilterMode filter;
  bool orthographic;
  glm::dvec3 eye;
  glm::dvec3 spacing;
  double angle;
};

// Kernel widths (sigma in voxel spacings) every invariant is checked at: narrow, the paper's,
// wide.
constexpr double kWidths[] = {0.6, 1.0, 1.6};

// One visible voxel in the middle of a 5^3 volume.
Volume singleVoxel(glm::dvec3 spacing) {
  return makeVolume(5, 5, 5, spacing,
                    [](int i, int j, int k) { return i == 2 && j == 2 && k == 2; });
}

TEST_F(SplatInvariants, ShaderFootprintEqualsCppReferenceAndKeepsMass) {
  const int w = 96, h = 80;
  const SplatCase cases[] = {
      {FilterMode::Ewa, false, {0.3, -0.2, 6.0}, {1, 1, 1}, 30},       // magnified, near the axis
      {FilterMode::Ewa, false, {3.0, 2.0, 5.0}, {1.0, 0.5, 2.0}, 40},  // rectilinear, oblique
      {FilterMode::Ewa, false, {0.0, 0.0, 400.0}, {1, 1, 1}, 30},  // minified: the low-pass wins
      {FilterMode::Plain, false, {1.0, 1.0, 8.0}, {1.0, 1.0, 1.0}, 30},
      {FilterMode::Swan, false, {0.0, 0.0, 400.0}, {1, 1, 1}, 30},  // beyond k
      {FilterMode::Ewa, true, {2.0, -3.0, 10.0}, {2.0, 1.0, 1.0}, 20},
      {FilterMode::Plain, true, {0.0, 0.0, 10.0}, {1.0, 1.0, 1.0}, 20},
  };
  for (const SplatCase& c : cases)
    for (double width : kWidths) {
      const Volume vol = singleVoxel(c.spacing);
      const TransferFunction tf = whiteTf(0.5, 1.0);
      renderer()->setVolume(vol);
      renderer()->setTransferFunction(tf);
      Camera cam;
      cam.focalPoint = vol.worldPosition(2, 2, 2) + glm::dvec3(0.2, -0.1, 0.0);
      cam.position = cam.focalPoint + c.eye;
      cam.viewAngleDeg = c.angle;
      cam.orthographic = c.orthographic;
      RenderSettings settings;
      settings.filter = c.filter;
      settings.mode = RenderMode::XRay;
      settings.kernelWidth = width;
      renderer()->render(cam, settings, w, h);
      const std::vector<float> depth = renderer()->readOpticalDepth();
      ASSERT_EQ(depth.size(), size_t(w) * h);

      // The same splat through the C++ reference.
      const Projection proj = cam.projection(w, h);
      const glm::dvec3 u =
          glm::dvec3(cam.viewMatrix() * glm::dvec4(vol.worldPosition(2, 2, 2), 1.0));
      const FootprintParams params = footprintParams(settings, c.spacing);
      const Footprint fp = computeFootprint(
          u, cameraCovariance(cam.rotation(), kernelSigma(c.spacing, width)), proj, params);
      ASSERT_TRUE(fp.visible);
      const double g = tf.extinctionAt(200.0) * c.spacing.x * c.spacing.y * c.spacing.z;
      double sum = 0.0, peak = 0.0, worst = 0.0;
      for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
          const double expected = g * footprintWeight(fp, {x + 0.5, y + 0.5}, params.cutoff);
          const double got = depth[size_t(y) * w + x];
          ASSERT_TRUE(std::isfinite(got));
          sum += got;
          peak = std::max(peak, expected);
          worst = std::max(worst, std::abs(got - expected));
        }
      }
      const std::string what = std::string(filterModeName(c.filter)) +
                               (c.orthographic ? " orthographic" : " perspective") +
                               ", kernel width " + std::to_string(width);
      EXPECT_LT(worst, 2e-3 * peak) << what << ": shader differs from the C++ footprint";
      if (fp.center.x - fp.radius > 0 && fp.center.x + fp.radius < w &&
          fp.center.y - fp.radius > 0 && fp.center.y + fp.radius < h &&
          std::sqrt(fp.covariance[0][0]) > 0.7) {
        EXPECT_NEAR(sum / (g * fp.jacobianDet), 1.0, 0.01) << what << ": image integral != mass";
      }
    }
}

TEST_F(SplatInvariants, QuadPathDrawsTheSameFootprintAsPointSprites) {
  const Volume vol = singleVoxel({1, 1, 1});
  renderer()->setVolume(vol);
  renderer()->setTransferFunction(whiteTf(0.5, 1.0));
  Camera cam;
  cam.focalPoint = vol.worldPosition(2, 2, 2);
  cam.position = cam.focalPoint + glm::dvec3(0.5, 0.3, 6.0);
  RenderSettings settings;
  settings.mode = RenderMode::XRay;
  renderer()->render(cam, settings, 64, 64);
  const std::vector<float> points = renderer()->readOpticalDepth();
  EXPECT_FALSE(renderer()->stats().quadPass);
  renderer()->setPointSizeLimit(8.0f);
  renderer()->render(cam, settings, 64, 64);
  const std::vector<float> quads = renderer()->readOpticalDepth();
  EXPECT_TRUE(renderer()->stats().quadPass);
  double total = 0.0;
  for (size_t p = 0; p < points.size(); ++p) {
    EXPECT_NEAR(points[p], quads[p], 1e-6) << "pixel " << p;
    total += points[p];
  }
  EXPECT_GT(total, 0.0);
}

// Opacity at the image centre of a slab of constant extinction seen head-on.
double centreOpacity(SplatRenderer& r, const Volume& vol, const TransferFunction& tf,
                     FilterMode filter, bool ortho, double kernelWidth,
                     ClassificationMode classification, bool slabPreintegration = true) {
  r.setVolume(vol);
  r.setTransferFunction(tf);
  Camera cam;
  const glm::dvec3 lo = vol.boundsMin(), hi = vol.boundsMax();
  cam.focalPoint = 0.5 * (lo + hi);
  // Close enough that the slab's sides are outside a 9x9 centre patch.
  cam.position = cam.focalPoint + glm::dvec3(0, 0, 2.0 * (hi.x - lo.x));
  cam.orthographic = ortho;
  RenderSettings settings;
  settings.filter = filter;
  settings.kernelWidth = kernelWidth;
  settings.classification.mode = classification;
  settings.slabPreintegration = slabPreintegration;
  r.render(cam, settings, 48, 48);
  const Image8 img = r.readImage();
  double sum = 0.0;
  for (int y = 20; y < 29; ++y)
    for (int x = 20; x < 29; ++x) sum += img.pixels[(size_t(y) * img.width + x) * 3];
  return sum / 81.0 / 255.0;
}

TEST_F(SplatInvariants, HomogeneousMediumHasOpacityOneMinusExpTauL) {
  for (double s : {0.5, 1.0, 2.0}) {
    const int n = 24, nz = 6;
    const Volume vol = makeVolume(n, n, nz, glm::dvec3(s), [](int, int, int) { return true; });
    // Pre-classified, the lattice of unit-mass kernels integrates to nz * s. Post-classified,
    // the field ends at the outermost voxel centres, as a ray caster's does: (nz - 1) * s.
    const double preL = nz * s, postL = (nz - 1) * s;
    const double tau = 1.2 / preL;
    const TransferFunction tf = whiteTf(1.0 - std::exp(-tau), 1.0);
    // Post-classified, the medium's constant value comes out of every slab's weighted mean
    // exactly and the covered lengths sum to the ray's length in the box: the same tolerance
    // holds, with slab pre-integration (constant pairs: the segment lengths sum to the same)
    // and without.
    const std::pair<ClassificationMode, bool> variants[] = {{ClassificationMode::Pre, true},
                                                            {ClassificationMode::Post, true},
                                                            {ClassificationMode::Post, false}};
    for (auto [c, pairs] : variants)
      for (FilterMode f : {FilterMode::Ewa, FilterMode::Swan, FilterMode::Plain})
        for (bool ortho : {false, true})
          for (double width : kWidths) {
            const double L = c == ClassificationMode::Pre ? preL : postL;
            const double expected = 1.0 - std::exp(-tau * L);
            const double got = centreOpacity(*renderer(), vol, tf, f, ortho, width, c, pairs);
            EXPECT_NEAR(got, expected, 0.03 * expected)
                << "spacing " << s << ", " << filterModeName(f)
                << (ortho ? " orthographic" : " perspective") << ", kernel width " << width << ", "
                << classificationModeName(c) << "-classified"
                << (pairs ? "" : " without slab pre-integration");
          }
  }
}

TEST_F(SplatInvariants, DegenerateViewsGiveFinitePictures) {
  const Volume cube = makeVolume(8, 8, 8, glm::dvec3(1.0), [](int, int, int) { return true; });
  renderer()->setVolume(cube);
  renderer()->setTransferFunction(whiteTf(0.3, 1.0));
  RenderSettings settings;
  settings.background = {0.0, 0.0, 1.0};
  Camera inside;  // the eye inside the volume: voxels behind it are culled
  inside.position = {3.5, 3.5, 3.5};
  inside.focalPoint = {3.5, 3.5, 0.0};
  renderer()->render(inside, settings, 32, 32);
  Image8 img = renderer()->readImage();
  EXPECT_GT(img.pixels[(16 * 32 + 16) * 3], 0);  // voxels in front are drawn
  Camera away;                                   // looking away from the volume: nothing in front
  away.position = {3.5, 3.5, 20.0};
  away.focalPoint = {3.5, 3.5, 40.0};
  renderer()->render(away, settings, 32, 32);
  img = renderer()->readImage();
  for (size_t p = 0; p < img.pixels.size(); p += 3) {
    ASSERT_EQ(img.pixels[p], 0);
    ASSERT_EQ(img.pixels[p + 2], 255);
  }
  // An all-transparent transfer function draws nothing.
  TransferFunction clear = whiteTf(0.0, 1.0);
  renderer()->setTransferFunction(clear);
  Camera front;
  front.position = {3.5, 3.5, 30.0};
  front.focalPoint = {3.5, 3.5, 3.5};
  renderer()->render(front, settings, 32, 32);
  EXPECT_EQ(renderer()->stats().splatsTotal, 0u);
  img = renderer()->readImage();
  EXPECT_EQ(img.pixels[(16 * 32 + 16) * 3 + 2], 255);
  // A 1x1x1 volume renders one splat.
  const Volume one = makeVolume(1, 1, 1, glm::dvec3(1.0), [](int, int, int) { return true; });
  renderer()->setVolume(one);
  renderer()->setTransferFunction(whiteTf(0.9, 1.0));
  front.focalPoint = {0, 0, 0};
  front.position = {0, 0, 10};
  renderer()->render(front, settings, 32, 32);
  EXPECT_EQ(renderer()->stats().splatsDrawn, 1u);
  img = renderer()->readImage();
  EXPECT_GT(img.pixels[(16 * 32 + 16) * 3], 20);
}

// The statistics panel's time per stage: classification only when the set is rebuilt, the
// stages within the whole call's time.
TEST_F(SplatInvariants, StageTimesAreMeasuredAndFitInTheFrame) {
  const Volume cube = makeVolume(12, 12, 12, glm::dvec3(1.0), [](int, int, int) { return true; });
  renderer()->setVolume(cube);
  renderer()->setTransferFunction(whiteTf(0.3, 1.0));
  Camera cam;
  cam.position = {5.5, 5.5, 40.0};
  cam.focalPoint = {5.5, 5.5, 5.5};
  RenderSettings settings;
  renderer()->render(cam, settings, 48, 48);
  RenderStats first = renderer()->stats();
  EXPECT_GT(first.classifyMs, 0.0);
  EXPECT_GT(first.partitionMs, 0.0);
  EXPECT_GT(first.splatMs, 0.0);
  EXPECT_GT(first.compositeMs, 0.0);
  EXPECT_LE(first.classifyMs + first.partitionMs + first.splatMs + first.compositeMs,
            first.renderMs * 1.0001);
  renderer()->render(cam, settings, 48, 48);  // same function: the splats are kept
  const RenderStats second = renderer()->stats();
  EXPECT_EQ(second.classifyMs, 0.0);
  EXPECT_GT(second.splatMs, 0.0);
}

// Stage times from GPU timestamps (hardware GL's default; forced here on the software
// rasterizer): the same picture, stages measured and within the frame, and the CPU's clock
// path gives the same statistics otherwise.
TEST_F(SplatInvariants, GpuTimestampsTimeTheStagesWithoutChangingThePicture) {
  const Volume cube = makeVolume(16, 16, 16, glm::dvec3(1.0), [](int, int, int) { return true; });
  renderer()->setVolume(cube);
  renderer()->setTransferFunction(whiteTf(0.3, 1.0));
  Camera cam;
  cam.position = {7.5, 7.5, 50.0};
  cam.focalPoint = {7.5, 7.5, 7.5};
  RenderSettings settings;
  settings.splatter = Splatter::Raster;  // timed frames: auto's second one would be in tiles
  renderer()->setPartition(PartitionMode::Cpu);  // the same order of sums both ways
  Image8 pictures[2];
  for (int timers = 0; timers < 2; ++timers) {
    renderer()->setGpuTimers(timers == 1);
    renderer()->render(cam, settings, 64, 64);
    renderer()->render(cam, settings, 64, 64);  // classified: the stages alone
    const RenderStats st = renderer()->stats();
    const std::string what = timers ? "GPU timestamps" : "CPU clock";
    EXPECT_GT(st.splatMs, 0.0) << what;
    EXPECT_GT(st.compositeMs, 0.0) << what;
    EXPECT_LE(st.partitionMs + st.splatMs + st.compositeMs, st.renderMs * 1.0001) << what;
    EXPECT_GT(st.slabsDrawn, 2u) << what;
    pictures[timers] = renderer()->readImage();
  }
  EXPECT_EQ(pictures[0].pixels, pictures[1].pixels);
}

// RenderStats::gpuBytes counts what the renderer allocated: the splat and attribute buffers
// (8 bytes a splat each), the transfer table (4096 RGBA32F texels), the frame's images (36
// bytes a pixel: the RGBA16F slab image of auto precision, the RGBA32F accumulation, the RGBA8
// output, the depth-stencil and the coarser slab images' marks) and the partition's buffers; a
// larger image adds exactly its pixels.
TEST_F(SplatInvariants, GpuBytesCountTheBuffersAndImagesAllocated) {
  const Volume cube = makeVolume(12, 12, 12, glm::dvec3(1.0), [](int, int, int) { return true; });
  renderer()->setVolume(cube);
  renderer()->setTransferFunction(whiteTf(0.3, 1.0));
  Camera cam;
  cam.position = {5.5, 5.5, 40.0};
  cam.focalPoint = {5.5, 5.5, 5.5};
  RenderSettings settings = paperSettings();         // pre-classified: the records counted below
  settings.occlusionCulling = OcclusionCulling::On;  // its pyramid is counted too
  renderer()->render(cam, settings, 48, 48);
  const RenderStats small = renderer()->stats();
  ASSERT_EQ(small.splatsTotal, 12u * 12u * 12u);
  // The splat records (8 bytes each; the attributes are not uploaded without shading or
  // surface splats: a 16-byte placeholder), the transfer table and the images.
  const size_t fixed = small.splatsTotal * 8 + 16 + 4096 * 16 + 48 * 48 * 36;
  // Plus the order list (at least 4 bytes an entry) and, for the GPU partition, its scratch
  // buffers, which keep the capacity earlier frames needed.
  EXPECT_GE(small.gpuBytes, fixed + small.splatsTotal * 4);
  renderer()->render(cam, settings, 96, 64);
  // Occlusion culling's pyramid: one byte per 2x2 pixels, padded to powers of two, and its
  // levels down to 1x1 (48x48: 32x32 ... 1x1; 96x64: 64x32 ... 1x1).
  const size_t pyramid48 = 1024 + 256 + 64 + 16 + 4 + 1;
  const size_t pyramid96x64 = 2048 + 512 + 128 + 32 + 8 + 2 + 1;
  EXPECT_EQ(renderer()->stats().gpuBytes - small.gpuBytes,
            size_t(96 * 64 - 48 * 48) * 36 + pyramid96x64 - pyramid48);
  // Shading reads the normals: 8 bytes a splat more, in place of the placeholder.
  const size_t unshaded = renderer()->stats().gpuBytes;
  settings.lighting.enabled = true;
  renderer()->render(cam, settings, 96, 64);
  EXPECT_EQ(renderer()->stats().gpuBytes - unshaded, small.splatsTotal * 8 - 16);
  settings.lighting.enabled = false;
  renderer()->render(cam, settings, 96, 64);
  EXPECT_EQ(renderer()->stats().gpuBytes, unshaded);
  // Post-classified with slab pre-integration: a second RGBA16F slab image, the 256x256
  // RGBA32F table and the 4096-entry R32F extinction prefix; in quarters (the default) two
  // RGBA16F back halves more; float slab images, 8 bytes a pixel more each; without
  // pre-integration, all are freed.
  settings.classification.mode = ClassificationMode::Post;
  settings.slabPreintegration = false;
  renderer()->render(cam, settings, 96, 64);
  const size_t single = renderer()->stats().gpuBytes;
  settings.slabPreintegration = true;
  settings.slabSamples = 2;
  renderer()->render(cam, settings, 96, 64);
  EXPECT_EQ(renderer()->stats().gpuBytes - single, size_t(96 * 64) * 8 + 256 * 256 * 16 + 4096 * 4);
  settings.slabSamples = 4;
  renderer()->render(cam, settings, 96, 64);
  EXPECT_EQ(renderer()->stats().gpuBytes - single,
            size_t(96 * 64) * 8 * 3 + 256 * 256 * 16 + 4096 * 4);
  const size_t halfQuarters = renderer()->stats().gpuBytes;
  settings.slabPrecision = SlabPrecision::Float;
  renderer()->render(cam, settings, 96, 64);
  EXPECT_EQ(renderer()->stats().gpuBytes - halfQuarters, size_t(96 * 64) * 8 * 4);
  settings.slabPrecision = SlabPrecision::Auto;
  settings.slabPreintegration = false;
  renderer()->render(cam, settings, 96, 64);
  EXPECT_EQ(renderer()->stats().gpuBytes, single);
}

// Auto takes half-float slab images only where they keep the pictures (docs/performance.md, "Slab
// image precision"): narrow kernels, not shaded post-classification with field or voxel normals
// (differences or sums in the slabs), never X-ray or MIP; half and float are taken as asked in the
// composite mode.
TEST(SlabPrecision, AutoTakesHalfFloatsOnlyWhereTheyHold) {
  RenderSettings s;  // post-classified, kernel width 0.7, unshaded
  EXPECT_TRUE(halfFloatSlabs(s));
  s.kernelWidth = 1.0;
  EXPECT_TRUE(halfFloatSlabs(s));
  s.kernelWidth = 1.6;
  EXPECT_FALSE(halfFloatSlabs(s));
  s.slabPrecision = SlabPrecision::Half;
  EXPECT_TRUE(halfFloatSlabs(s));
  s = RenderSettings{};
  s.lighting.enabled = true;  // normals read from the gradient texture, not the slabs
  EXPECT_TRUE(halfFloatSlabs(s));
  for (PostNormals normals : {PostNormals::Field, PostNormals::Voxel}) {
    s.postNormals = normals;
    EXPECT_FALSE(halfFloatSlabs(s)) << postNormalsName(normals);
  }
  s.classification.mode = ClassificationMode::Pre;  // shaded per splat: the sums hold colours
  EXPECT_TRUE(halfFloatSlabs(s));
  s.slabPrecision = SlabPrecision::Float;
  EXPECT_FALSE(halfFloatSlabs(s));
  s = RenderSettings{};
  s.slabPrecision = SlabPrecision::Half;
  for (RenderMode m : {RenderMode::XRay, RenderMode::Mip}) {
    s.mode = m;
    EXPECT_FALSE(halfFloatSlabs(s));
  }
  SlabPrecision p = SlabPrecision::Auto;
  EXPECT_TRUE(parseSlabPrecision("float", &p));
  EXPECT_EQ(p, SlabPrecision::Float);
  EXPECT_FALSE(parseSlabPrecision("double", &p));
  EXPECT_STREQ(slabPrecisionName(SlabPrecision::Half), "half");
}

}  // namespace
}  // namespace ewa::test
