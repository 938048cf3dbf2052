// The CPU splatter's composite without GL: its AVX2 build draws the baseline build's picture,
// a frame of many slabs draws something, early termination leaves opaque pixels opaque, and
// a frame's passes draw its one-pass picture holding a fraction of the bytes.
#include "core/tile_compositor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/camera.h"
#include "core/covered_length.h"
#include "core/kernel_reach.h"
#include "core/slab_partition.h"
#include "core/splat_attributes.h"
#include "core/splat_records.h"
#include "core/synthetic_volume.h"
#include "core/volume_orientation.h"

namespace ewa {
namespace {

// A pre-classified frame of `spec` from an oblique perspective camera, as the splat renderer
// sets it up (kernels 0.7 wide, cutoff 5, depth cutoff 1, slabs 2 spacings thick).
struct Frame {
  ClassifiedSplats splats;
  SplatFrameSetup setup;
  SlabPartition partition;
  TileCompositeSettings settings;
};

Frame makeFrame(const std::string& spec, const std::vector<HalfSpace>& clipPlanes = {}) {
  const SyntheticVolume synthetic = makeSyntheticVolume(spec);
  const Volume& v = synthetic.volume;
  const TransferFunction& tf = *synthetic.transferFunction;
  Frame f;
  f.splats = classifySplats(v, tf, {});
  const ClassifiedSplats& splats = f.splats;
  Camera world;
  world.focalPoint = v.origin() + 0.5 * glm::dvec3(v.dims()[0], v.dims()[1], v.dims()[2]);
  world.position = world.focalPoint + glm::dvec3(20.0, 14.0, 50.0);
  const Camera cam = cameraInVolumeFrame(world, v);
  const int width = 61, height = 53;  // not a multiple of the tile
  SplatFrameSetup& setup = f.setup;
  setup.view = cam.viewMatrix();
  setup.origin = v.origin();
  setup.spacing = v.spacing();
  setup.kernelWidth = 0.7;
  setup.proj = cam.projection(width, height);
  setup.params.cutoff = 5.0;
  setup.reach = kernelReach(setup.proj, FilterMode::Ewa, 5.0, v.spacing(), 0.7, 1.0);
  setup.transfer = tf.bake(v.minValue(), v.maxValue(), 4096);
  setup.clipPlanes = clipPlanes;
  DepthExtent extent;
  extent.reach = setup.reach;
  extent.rotation = cam.rotation();
  extent.spacing = v.spacing();
  extent.kernelWidth = 0.7;
  f.partition.build(splats.splats, {}, v.origin(), setup.view, 2.0, setup.params.cullDepth, extent);
  f.settings.width = width;
  f.settings.height = height;
  f.settings.cutoff = 5.0;
  f.settings.profile = depthProfile(1.0);
  f.settings.clipPlanes = clipPlanes;
  f.settings.proj = setup.proj;
  f.settings.cameraToIndex = cameraToIndex(v, cam);
  f.settings.dataBox = v.indexDataBox();
  return f;
}

std::vector<glm::vec4> draw(const Frame& f, bool avx2, double termination = 0.99,
                            size_t passSlabs = 0, TileCompositor::Timing* timing = nullptr) {
  TileCompositor compositor;
  compositor.setAvx2(avx2);
  compositor.setPassSlabs(passSlabs);
  TileCompositeSettings settings = f.settings;
  settings.termination = termination;
  std::vector<glm::vec4> picture;
  const TileCompositor::Timing t =
      compositor.draw(SplatRecordMaker(f.splats.splats, f.splats.attributes, f.setup),
                      f.partition.order(), f.partition.slabs(), settings, picture);
  if (timing) *timing = t;
  return picture;
}

float largestDifference(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  float worst = 0.0f;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
    for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(a[i][c] - b[i][c]));
  return a.size() == b.size() ? worst : 1e30f;
}

TEST(TileCompositor, Avx2BuildDrawsTheBaselinePicture) {
  // Cut profile (erf series) and uncut (erfApprox); unclipped and clipped.
  const HalfSpace cut{glm::normalize(glm::dvec3(1.0, 0.3, -0.2)), 0.0};
  for (bool clipped : {false, true}) {
    SCOPED_TRACE(clipped);
    Frame f = makeFrame("marschner-lobb:24");
    ASSERT_GT(f.partition.slabs().size(), 5u);
    if (clipped) {
      // A plane through the volume's middle, in camera space.
      const glm::dvec3 centre(0.0, 0.0, -glm::length(glm::dvec3(20.0, 14.0, 50.0)));
      f.settings.clipPlanes = {HalfSpace{cut.normal, -glm::dot(cut.normal, centre)}};
    }
    for (double depthCutoff : {1.0, double(INFINITY)}) {
      f.settings.profile = depthProfile(depthCutoff);
      const std::vector<glm::vec4> baseline = draw(f, false), avx2 = draw(f, true);
      float opacity = 0.0f;
      for (const glm::vec4& p : baseline) opacity = std::max(opacity, p.a);
      EXPECT_GT(opacity, 0.3f) << "the picture should not be empty";
      // Float sums in another order and FMA's rounding.
      EXPECT_LE(largestDifference(baseline, avx2), 1e-5f);  // measured: below 1e-6
    }
  }
}

TEST(TileCompositor, TerminationStopsPixelsPastTheThreshold) {
  const Frame f = makeFrame("sphere:24");
  const std::vector<glm::vec4> all = draw(f, true, 1.0);
  float most = 0.0f;
  for (const glm::vec4& p : all) most = std::max(most, p.a);
  ASSERT_GT(most, 0.1f);
  const float threshold = 0.5f * most;
  const std::vector<glm::vec4> stopped = draw(f, true, threshold);
  size_t opaque = 0;
  for (size_t i = 0; i < all.size(); ++i) {
    // A stopped pixel keeps what it had when it passed the threshold: at most the whole.
    EXPECT_LE(stopped[i].a, all[i].a + 1e-5f);
    if (stopped[i].a >= threshold) {
      ++opaque;
    } else {
      EXPECT_NEAR(stopped[i].a, all[i].a, 1e-5f) << "an open pixel takes every slab";
    }
  }
  EXPECT_GT(opaque, 0u);
}

TEST(TileCompositor, PassesDrawTheOnePassPictureWithAFractionOfTheBytes) {
  // Every gather and both orders, with and without termination: a tile's state carried from
  // pass to pass (picture, open pixels, the slab before's values, the splats' records at
  // their later slabs) changes nothing.
  Frame f = makeFrame("marschner-lobb:24");
  ASSERT_GT(f.partition.slabs().size(), 8u);
  f.settings.profile = depthProfile(1.0);
  std::vector<glm::vec4> pairs(64 * 64, glm::vec4(0.2f, 0.4f, 0.6f, 0.3f));
  std::vector<float> prefix(64);
  for (size_t i = 0; i < prefix.size(); ++i) prefix[i] = 0.05f * float(i);
  f.settings.tables.pairTexels = pairs.data();
  f.settings.tables.pairSize = 64;
  f.settings.tables.prefix = prefix.data();
  f.settings.tables.prefixSize = int(prefix.size());
  for (TileGather gather : {TileGather::Pre, TileGather::Post, TileGather::XRay, TileGather::Mip})
    for (bool backToFront : {false, true})
      for (double termination : {0.5, 1.0}) {
        SCOPED_TRACE(testing::Message() << int(gather) << backToFront << termination);
        f.settings.gather = gather;
        f.settings.backToFront = backToFront;
        TileCompositor::Timing one, many;
        const std::vector<glm::vec4> whole = draw(f, true, termination, SIZE_MAX, &one);
        const std::vector<glm::vec4> passes = draw(f, true, termination, 2, &many);
        float alpha = 0.0f;
        for (const glm::vec4& p : whole) alpha = std::max({alpha, p.r, p.a});
        EXPECT_GT(alpha, 0.05f) << "the picture should not be empty";
        // The same sums in the same order; a slab finished at a pass's end goes through the
        // composite's other inlined copy, whose FMAs may round apart (measured: 6e-8).
        EXPECT_LE(largestDifference(whole, passes), 1e-6f);
        // Tiles done in a pass take no items in the later ones.
        EXPECT_LE(many.entries, one.entries);
        // A pass of 2 of the 14 slabs holds a fraction of the records and bins (a splat's
        // place besides).
        EXPECT_LT(double(many.bytes), 0.5 * double(one.bytes));
      }
}

TEST(TileCompositor, AFrameOverItsBudgetGoesInPassesOfAFewBytesASplat) {
  const Frame f = makeFrame("marschner-lobb:24");
  const size_t splats = f.splats.splats.size();
  const auto bytesPerSplat = [&](size_t budget) {
    TileCompositor compositor;
    compositor.setPassBytes(budget);
    std::vector<glm::vec4> picture;
    const TileCompositor::Timing t =
        compositor.draw(SplatRecordMaker(f.splats.splats, f.splats.attributes, f.setup),
                        f.partition.order(), f.partition.slabs(), f.settings, picture);
    return double(t.bytes) / double(splats);
  };
  // Within the budget: one pass, a record a splat and more.
  EXPECT_GT(bytesPerSplat(TileCompositor::kPassBytes), double(sizeof(SplatRecord)));
  EXPECT_GT(bytesPerSplat(0), double(sizeof(SplatRecord)));  // passBudget: a small frame's
  // Over it: a slab a pass here (14 slabs), the records and bins under 32 bytes a splat.
  EXPECT_LE(bytesPerSplat(1), 32.0);
}

TEST(TileCompositor, TheBudgetIsAFewBytesASplatWithinItsBounds) {
  EXPECT_EQ(TileCompositor::passBudget(1000), TileCompositor::kPassBytesLeast);
  EXPECT_EQ(TileCompositor::passBudget(2000000), 2000000 * TileCompositor::kPassBytesPerSplat);
  EXPECT_EQ(TileCompositor::passBudget(100000000), TileCompositor::kPassBytes);
  EXPECT_LT(TileCompositor::kPassBytesLeast, TileCompositor::kPassBytes);
}

}  // namespace
}  // namespace ewa
