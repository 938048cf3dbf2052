// The CPU splatter's composite without GL: its AVX2 build draws the baseline build's picture,
// a frame of many slabs draws something, and early termination leaves opaque pixels opaque.
#include "core/tile_compositor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/camera.h"
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
  std::vector<SplatRecord> records;
  SlabPartition partition;
  TileCompositeSettings settings;
};

Frame makeFrame(const std::string& spec, const std::vector<HalfSpace>& clipPlanes = {}) {
  const SyntheticVolume synthetic = makeSyntheticVolume(spec);
  const Volume& v = synthetic.volume;
  const TransferFunction& tf = *synthetic.transferFunction;
  const ClassifiedSplats splats = classifySplats(v, tf, {});
  Camera world;
  world.focalPoint = v.origin() + 0.5 * glm::dvec3(v.dims()[0], v.dims()[1], v.dims()[2]);
  world.position = world.focalPoint + glm::dvec3(20.0, 14.0, 50.0);
  const Camera cam = cameraInVolumeFrame(world, v);
  const int width = 61, height = 53;  // not a multiple of the tile
  SplatFrameSetup setup;
  setup.view = cam.viewMatrix();
  setup.origin = v.origin();
  setup.spacing = v.spacing();
  setup.kernelWidth = 0.7;
  setup.proj = cam.projection(width, height);
  setup.params.cutoff = 5.0;
  setup.reach = kernelReach(setup.proj, FilterMode::Ewa, 5.0, v.spacing(), 0.7, 1.0);
  setup.transfer = tf.bake(v.minValue(), v.maxValue(), 4096);
  setup.clipPlanes = clipPlanes;
  Frame f;
  makeSplatRecords(splats.splats, splats.attributes, setup, f.records);
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
  return f;
}

std::vector<glm::vec4> draw(const Frame& f, bool avx2, double termination = 0.99) {
  TileCompositor compositor;
  compositor.setAvx2(avx2);
  TileCompositeSettings settings = f.settings;
  settings.termination = termination;
  std::vector<glm::vec4> picture;
  compositor.draw(f.records, f.partition.order(), f.partition.slabs(), settings, picture);
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

}  // namespace
}  // namespace ewa
