// Renderers sharing one SplatProgramSet (the window's levels of detail): each frame keeps its
// own programs' state (its coarser slab images' scale too), and a second renderer compiles
// nothing the first compiled.
#include "render/splat_program_set.h"

#include <gtest/gtest.h>

#include <memory>

#include "core/synthetic_volume.h"
#include "image_compare.h"
#include "render/splat_renderer.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class SplatProgramSetTest : public RenderFixture {};

constexpr double kTinyBudgetMs = 1e-6;

TEST_F(SplatProgramSetTest, SharingRenderersKeepTheirOwnFrames) {
  const gl::ShaderLibrary shaders;
  auto programs = std::make_shared<SplatProgramSet>(shaders);
  SplatRenderer a(shaders, programs), b(shaders, programs);
  a.setPartition(PartitionMode::Cpu);
  b.setPartition(PartitionMode::Cpu);
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:24");
  const SyntheticVolume ball = makeSyntheticVolume("sphere:20");
  a.setVolume(ml.volume);
  a.setTransferFunction(*ml.transferFunction);
  b.setVolume(ball.volume);
  b.setTransferFunction(*ball.transferFunction);
  Camera camA, camB;
  camA.focalPoint = glm::dvec3(11.5);
  camA.position = {30.0, -8.0, 34.0};  // near: A's front slabs go to coarser images
  camA.viewUp = {0.0, 0.0, 1.0};
  camB.frame(ball.volume.boundsMin(), ball.volume.boundsMax(), {1.0, 0.2, 0.1}, {0, 0, 1}, 1.2);
  RenderSettings settingsA = rasterSettings();  // stepped slab by slab
  settingsA.slabThickness = 1.0;                // many slabs: many steps
  RenderSettings settingsB = rasterSettings();  // another variant: pre-classified, shaded
  settingsB.classification.mode = ClassificationMode::Pre;
  settingsB.lighting.enabled = true;

  a.render(camA, settingsA, 64, 64);
  const Image8 wholeA = a.readImage();
  ASSERT_GT(a.stats().slabsCoarse, 0u);
  const size_t variantsA = programs->splat.compiled();
  b.render(camB, settingsB, 48, 48);
  const Image8 wholeB = b.readImage();
  ASSERT_GT(meanValue(wholeA), 3.0);
  ASSERT_GT(meanValue(wholeB), 3.0);
  EXPECT_GT(programs->splat.compiled(), variantsA);  // B's variant, compiled once for both

  // A's frame in steps, B drawing whole frames in between: A re-sets its variant and uniforms.
  a.beginFrame(camA, settingsA, 64, 64);
  int steps = 0;
  while (!a.stepFrame(kTinyBudgetMs)) {
    if (++steps % 5 == 0) b.render(camB, settingsB, 48, 48);
  }
  EXPECT_GT(steps, 10);
  EXPECT_LE(maxDifference(a.readImage(), wholeA), 1);
  EXPECT_EQ(b.readImage().pixels, wholeB.pixels);

  // A third renderer of A's settings compiles nothing new.
  const size_t splatVariants = programs->splat.compiled();
  const size_t slabVariants = programs->slab.compiled();
  SplatRenderer c(shaders, programs);
  c.setPartition(PartitionMode::Cpu);
  c.setVolume(ml.volume);
  c.setTransferFunction(*ml.transferFunction);
  c.render(camA, settingsA, 64, 64);
  EXPECT_EQ(c.readImage().pixels, wholeA.pixels);
  EXPECT_EQ(programs->splat.compiled(), splatVariants);
  EXPECT_EQ(programs->slab.compiled(), slabVariants);
}

// Frames drawn in compute tiles (RenderSettings::splatter): the set's tile programs are made by
// the first renderer that draws in tiles, and a second renderer compiles none of them again.
TEST_F(SplatProgramSetTest, SharingRenderersShareTheTilePrograms) {
  const gl::ShaderLibrary shaders;
  auto programs = std::make_shared<SplatProgramSet>(shaders);
  SplatRenderer a(shaders, programs), b(shaders, programs);
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:24");
  Camera cam;
  cam.frame(ml.volume.boundsMin(), ml.volume.boundsMax(), {0.3, -0.5, 1.0}, {0, 1, 0}, 1.0);
  RenderSettings settings;
  settings.splatter = Splatter::Tiles;
  for (SplatRenderer* r : {&a, &b}) {
    r->setPartition(PartitionMode::Cpu);
    r->setVolume(ml.volume);
    r->setTransferFunction(*ml.transferFunction);
  }
  EXPECT_EQ(programs->tiles, nullptr) << "made only when a renderer draws in tiles";
  a.render(cam, settings, 48, 48);
  ASSERT_TRUE(a.stats().tiles);
  ASSERT_NE(programs->tiles, nullptr);
  const TileEwaPrograms* first = programs->tiles.get();
  const size_t compiled = programs->tiles->compiled();
  EXPECT_GE(compiled, 5u);  // footprints, count, scan, scatter, composite
  b.render(cam, settings, 48, 48);
  ASSERT_TRUE(b.stats().tiles);
  EXPECT_EQ(programs->tiles.get(), first);
  EXPECT_EQ(programs->tiles->compiled(), compiled);
  EXPECT_EQ(b.readImage().pixels, a.readImage().pixels);
  EXPECT_GT(meanValue(a.readImage()), 3.0);
}

}  // namespace
}  // namespace ewa::test
