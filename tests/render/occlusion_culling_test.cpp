// Occlusion culling: splats over pixels already opaque are skipped, and the picture is the
// same to the bit, for points and quads, both partitions and drawing in budgeted steps.
#include <cstdlib>

#include "render_fixture.h"

namespace ewa::test {
namespace {

class OcclusionCulling : public RenderFixture {};

// A dense wall over the left half of the view at the front (z 20..25), a faint, wide slab
// behind it (z 2..17) over the whole view: behind the wall the faint splats are occluded,
// elsewhere the picture stays translucent, so early termination never ends the frame.
Volume wallAndHaze() {
  const int n = 28;
  std::vector<uint8_t> bytes(size_t(n) * n * n, 0);
  for (int k = 0; k < n; ++k)
    for (int j = 2; j < n - 2; ++j)
      for (int i = 2; i < n - 2; ++i) {
        uint8_t v = 0;
        if (k >= 20 && k <= 25 && i < n / 2) v = 250;
        if (k >= 2 && k <= 17) v = 60;
        bytes[i + n * (j + size_t(n) * k)] = v;
      }
  return Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, std::move(bytes));
}

TransferFunction wallTf() {
  TransferFunction tf;
  tf.opacity = {{30.0, 0.0}, {60.0, 0.03}, {200.0, 0.03}, {240.0, 1.0}, {255.0, 1.0}};
  tf.color = {{0.0, {0.2, 0.5, 1.0}}, {150.0, {0.2, 0.5, 1.0}}, {255.0, {1.0, 0.8, 0.3}}};
  tf.opacityUnitDistance = 1.0;
  return tf;
}

Camera frontCamera() {
  Camera cam;
  cam.focalPoint = {13.5, 13.5, 13.5};
  cam.position = {20.0, 17.0, 75.0};  // slightly oblique: footprints straddle the wall's edge
  cam.viewAngleDeg = 28.0;
  return cam;
}

struct Drawn {
  Image8 image;
  RenderStats stats;
};

Drawn draw(SplatRenderer& r, const RenderSettings& settings, bool stepped) {
  if (stepped) {
    r.beginFrame(frontCamera(), settings, 72, 64);
    int steps = 0;
    while (!r.stepFrame(0.5)) ++steps;
    EXPECT_GT(steps, 0) << "the budget should split the frame";
  } else {
    r.render(frontCamera(), settings, 72, 64);
  }
  return {r.readImage(), r.stats()};
}

TEST_F(OcclusionCulling, CullsHiddenSplatsAndKeepsThePictureExactly) {
  const Volume vol = wallAndHaze();
  renderer()->setVolume(vol);
  renderer()->setTransferFunction(wallTf());
  struct Case {
    const char* name;
    float pointLimit;  // 1: every splat through the quad path
    PartitionMode partition;
    bool stepped;
  };
  for (const Case& c : {Case{"points, GPU partition", 1e9f, PartitionMode::Gpu, false},
                        Case{"quads, GPU partition", 1.0f, PartitionMode::Gpu, false},
                        Case{"points, CPU partition", 1e9f, PartitionMode::Cpu, false},
                        Case{"points, budgeted steps", 1e9f, PartitionMode::Cpu, true}}) {
    SCOPED_TRACE(c.name);
    renderer()->setPointSizeLimit(c.pointLimit);
    renderer()->setPartition(c.partition);
    RenderSettings settings = paperSettings();
    settings.occlusionCulling = ewa::OcclusionCulling::Off;
    const Drawn off = draw(*renderer(), settings, c.stepped);
    settings.occlusionCulling = ewa::OcclusionCulling::On;
    const Drawn on = draw(*renderer(), settings, c.stepped);
    EXPECT_EQ(off.stats.entriesCulled, 0u);
    EXPECT_EQ(on.stats.slabEntries, off.stats.slabEntries);
    EXPECT_EQ(on.stats.slabsDrawn, off.stats.slabsDrawn) << "termination must not end the frame";
    // The haze behind the wall is a large share of the draws: a good part of them is culled.
    EXPECT_GT(on.stats.entriesCulled, on.stats.slabEntries / 10);
    EXPECT_LT(on.stats.entriesCulled, on.stats.slabEntries);
    ASSERT_EQ(on.image.pixels.size(), off.image.pixels.size());
    // To the bit with the CPU partition. The GPU's scatters each slab's entries in an order that
    // varies between frames (atomics), so its sums may round a level apart in a few pixels.
    const int allowed = c.partition == PartitionMode::Cpu ? 0 : 1;
    size_t differing = 0;
    for (size_t p = 0; p < on.image.pixels.size(); ++p)
      differing += std::abs(int(on.image.pixels[p]) - int(off.image.pixels[p])) > allowed;
    EXPECT_EQ(differing, 0u) << "culling changed the picture";
  }
}

TEST_F(OcclusionCulling, NothingCulledWithoutEarlyTermination) {
  const Volume vol = wallAndHaze();
  renderer()->setVolume(vol);
  renderer()->setTransferFunction(wallTf());
  RenderSettings settings = paperSettings();
  // Auto culls where the renderer says it does (hardware GL), not on software rasterizers.
  const bool automatic = renderer()->occlusionCulling(ewa::OcclusionCulling::Auto);
  EXPECT_EQ(draw(*renderer(), settings, false).stats.entriesCulled > 0, automatic);
  settings.occlusionCulling = ewa::OcclusionCulling::On;
  settings.terminationOpacity = 1.0;  // no pixel is ever marked opaque
  EXPECT_EQ(draw(*renderer(), settings, false).stats.entriesCulled, 0u);
  settings.terminationOpacity = 0.99;
  settings.order = CompositeOrder::BackToFront;
  EXPECT_EQ(draw(*renderer(), settings, false).stats.entriesCulled, 0u);
  settings.order = CompositeOrder::FrontToBack;
  EXPECT_GT(draw(*renderer(), settings, false).stats.entriesCulled, 0u);
}

}  // namespace
}  // namespace ewa::test
