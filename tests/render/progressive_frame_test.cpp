// Progressive frames: beginFrame + stepFrame with a tiny budget draw the same picture as
// render(), in many steps, while readImage() keeps the last complete picture until the end.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <thread>

#include "core/synthetic_volume.h"
#include "gl/shader_library.h"
#include "image_compare.h"
#include "io/png_io.h"
#include "render/lod_renderer.h"
#include "render_fixture.h"
#include "ui/progressive_refinement.h"

namespace ewa::test {
namespace {

class ProgressiveFrame : public RenderFixture {};

// A budget no step can meet: every step draws the least it may (a slab's smallest range of
// entries; X-ray and MIP: the smallest range of their one slab).
constexpr double kTinyBudgetMs = 1e-6;

// Drawn slab by slab (rasterized), in many thin slabs: many steps. Float slab images: the GPU
// partition's order of a slab's entries varies between frames, and half-float sums round it 2-3
// levels apart (H200), floats within one.
RenderSettings manySlabs() {
  RenderSettings settings = rasterSettings();
  settings.slabThickness = 1.0;
  settings.slabPrecision = SlabPrecision::Float;
  return settings;
}

struct Stepped {
  Image8 image;
  int steps = 0;
  int setupSteps = 0;  // steps before anything was drawn (partition, order list pieces)
  RenderStats stats;
};

// Steps a frame to the end, checking after every unfinished step that the picture shown is
// still `previous` and that the progress grows.
Stepped stepToEnd(SplatRenderer& r, const Camera& cam, const RenderSettings& settings, int size,
                  const Image8& previous) {
  Stepped out;
  r.beginFrame(cam, settings, size, size);
  EXPECT_EQ(r.frameProgress(), 0.0);
  double progress = 0.0;
  while (!r.stepFrame(kTinyBudgetMs)) {
    ++out.steps;
    // Steps before the first slab is drawn may only wait for the partition worker or copy a
    // piece of the order list; from then on every step draws.
    if (progress > 0.0)
      EXPECT_GT(r.frameProgress(), progress) << "step " << out.steps;
    else
      EXPECT_GE(r.frameProgress(), 0.0);
    EXPECT_LT(r.frameProgress(), 1.0);
    if (r.frameProgress() == 0.0) ++out.setupSteps;
    progress = r.frameProgress();
    if (out.steps % 7 == 1) {  // reading back is slow; every few steps is enough
      const Image8 shown = r.readImage();
      EXPECT_EQ(maxDifference(shown, previous), 0) << "step " << out.steps;
    }
    if (out.steps > 100000) break;
  }
  ++out.steps;
  EXPECT_EQ(r.frameProgress(), 1.0);
  out.image = r.readImage();
  out.stats = r.stats();
  return out;
}

class ProgressiveModes : public ProgressiveFrame,
                         public ::testing::WithParamInterface<const char*> {};

// Stepping draws the same GL work in the same order as render(): the pictures are expected
// equal; the tolerance is one level per channel (of 255) for a driver that rounds a blend
// differently across a glFinish.
TEST_P(ProgressiveModes, TinyBudgetStepsGiveRendersPicture) {
  const std::string mode = GetParam();
  const SyntheticVolume s = makeSyntheticVolume("marschner-lobb:32");
  // Early termination needs a picture that turns opaque: a dense cube filling the view.
  const Volume cube = makeVolume(24, 24, 24, glm::dvec3(1.0), [](int, int, int) { return true; });
  const bool terminate = mode == "terminate";
  const Volume& volume = terminate ? cube : s.volume;
  SplatRenderer& r = *renderer();
  // Stepped and whole frames stop at the same slab when both wait for the termination
  // check's answer; a GPU's lagged answer comes when it comes (SlabCompositing tests it).
  r.setLaggedTermination(false);
  r.setVolume(volume);
  // Opacity 0.4 a voxel: opaque after some ten slabs, so termination comes after a few checks.
  r.setTransferFunction(terminate ? whiteTf(0.4, 1.0) : *s.transferFunction);
  RenderSettings settings = rasterSettings();  // stepped slab by slab
  settings.slabThickness = 1.0;                // many slabs: many steps
  // The GPU partition's order of a slab's entries varies between frames: half-float sums
  // round it 2-3 levels apart (H200), floats within one.
  settings.slabPrecision = SlabPrecision::Float;
  if (mode == "back-to-front") settings.order = CompositeOrder::BackToFront;
  if (mode == "xray") settings.mode = RenderMode::XRay;
  if (mode == "mip") settings.mode = RenderMode::Mip;
  if (mode == "shading") settings.lighting.enabled = true;
  Camera a, b;
  a.frame(volume.boundsMin(), volume.boundsMax(), {0.2, 0.3, 1.0}, {0, 1, 0}, 1.0);
  b.frame(volume.boundsMin(), volume.boundsMax(), {1.0, -0.4, 0.3}, {0, 0, 1}, 1.0);
  if (terminate) {  // head-on, the front face covering the whole image
    b = Camera{};
    b.focalPoint = {11.5, 11.5, 11.5};
    b.position = {11.5, 11.5, 60.0};
    b.viewAngleDeg = 15.0;
  }
  constexpr int kSize = 96;
  // Both partitions: the GPU's (the fixture's choice) and the CPU's, built on a worker thread.
  for (PartitionMode partition : {PartitionMode::Gpu, PartitionMode::Cpu}) {
    SCOPED_TRACE(partitionModeName(partition));
    r.setPartition(partition);
    r.render(a, settings, kSize, kSize);
    const Image8 before = r.readImage();
    r.render(b, settings, kSize, kSize);
    const Image8 whole = r.readImage();
    const RenderStats wholeStats = r.stats();
    ASSERT_GT(meanValue(whole), 3.0) << "nothing to compare";
    ASSERT_GT(maxDifference(before, whole), 20) << "the two views must differ";

    r.render(a, settings, kSize, kSize);
    // The picture shown while stepping: this one (the GPU partition's order of a slab's
    // entries, and the sums' rounding with it, may vary from frame to frame).
    const Image8 shown = r.readImage();
    // The CPU partition's order list goes up in pieces of 700 entries, one a step, each into a
    // page of its own (a 512^3 volume's in 4 MiB pieces); render() above copied it whole.
    // Draws then end at page boundaries as well as at storage-block windows.
    r.setOrderUploadPiece(700);
    const Stepped stepped = stepToEnd(r, b, settings, kSize, shown);
    const size_t pages = r.orderPageCount();
    r.setOrderUploadPiece(OrderPages::kDefaultPageEntries);
    if (partition == PartitionMode::Cpu) {
      EXPECT_GE(size_t(stepped.setupSteps), wholeStats.slabEntries / 700 - 1) << mode;
      EXPECT_GE(pages, (wholeStats.slabEntries + 699) / 700) << mode;
    }
    writePng(testOutputDir() + "/progressive_" + mode + "_" + partitionModeName(partition) + ".png",
             stepped.image);
    EXPECT_LE(maxDifference(stepped.image, whole), 1) << mode;
    EXPECT_EQ(stepped.stats.slabsDrawn, wholeStats.slabsDrawn);
    EXPECT_EQ(stepped.stats.slabEntries, wholeStats.slabEntries);
    if (settings.mode == RenderMode::Composite) {
      // A step draws one slab, or one range of at most 512 of a slab's entries (the first step
      // of a fresh renderer, before anything is measured: up to 2048): the slabs here are
      // bigger, so they are drawn in ranges over several steps.
      EXPECT_GE(size_t(stepped.steps), wholeStats.slabsDrawn - 2048 / 512);
      EXPECT_GE(size_t(stepped.steps), (wholeStats.slabEntries - 2048) / 512);
      EXPECT_GT(wholeStats.slabEntries / wholeStats.slabsDrawn, 512u);
      EXPECT_GT(wholeStats.slabsDrawn, terminate ? 4u : 10u);
      if (mode == "terminate") {
        EXPECT_LT(wholeStats.slabsDrawn, wholeStats.slabs);
      }
    } else {
      // The smallest range of entries a step (1024; the first step of a fresh renderer: 4096):
      // several steps for this volume.
      EXPECT_GE(size_t(stepped.steps), (wholeStats.slabEntries - 4096) / 1024);
      EXPECT_GT(stepped.steps, 3);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, ProgressiveModes,
                         ::testing::Values("front-to-back", "back-to-front", "terminate", "xray",
                                           "mip", "shading"));

// A budget that never runs out draws the whole frame in the first step, also when the step
// before was cut short inside a slab (a fresh renderer's first, unmeasured chunk).
TEST_F(ProgressiveFrame, AmpleBudgetFinishesInOneStep) {
  const SyntheticVolume s = makeSyntheticVolume("marschner-lobb:32");
  const gl::ShaderLibrary shaders;
  SplatRenderer r(shaders);
  r.setVolume(s.volume);
  r.setTransferFunction(*s.transferFunction);
  RenderSettings settings = rasterSettings();     // stepped slab by slab
  settings.slabThickness = 6.0;                   // slabs of more entries than a first chunk holds
  settings.slabPrecision = SlabPrecision::Float;  // see TinyBudgetStepsGiveRendersPicture
  Camera cam;
  cam.frame(s.volume.boundsMin(), s.volume.boundsMax(), {0.2, 0.3, 1.0}, {0, 1, 0}, 1.0);
  r.render(cam, settings, 64, 64);
  const Image8 whole = r.readImage();
  ASSERT_GT(r.stats().slabEntries / r.stats().slabsDrawn, 2048u);
  r.beginFrame(cam, settings, 64, 64);
  EXPECT_FALSE(r.stepFrame(kTinyBudgetMs));  // inside the first slab
  EXPECT_TRUE(r.stepFrame(1e30));
  EXPECT_LE(maxDifference(r.readImage(), whole), 1);
  for (double budget : {1e30, 1e6}) {
    r.beginFrame(cam, settings, 64, 64);
    EXPECT_TRUE(r.stepFrame(budget)) << budget;
    EXPECT_LE(maxDifference(r.readImage(), whole), 1) << budget;
  }
}

// Once its prices are measured, a step whose entries have spent its budget leaves the slab's
// finish to later steps, and a finish too dear for one step (its pass over the slab's
// rectangle: on llvmpipe at 1024x768 dearer than a UI frame's whole budget) is drawn in bands
// of rows over several steps, the final pass in one of its own; the picture is the same.
TEST_F(ProgressiveFrame, SpentStepLeavesTheSlabsPassToLaterStepsInBands) {
  const SyntheticVolume s = makeSyntheticVolume("marschner-lobb:32");
  SplatRenderer& r = *renderer();
  r.setPartition(PartitionMode::Cpu);  // entries counted as they are drawn
  r.setVolume(s.volume);
  r.setTransferFunction(*s.transferFunction);
  RenderSettings settings = rasterSettings();     // stepped slab by slab
  settings.slabThickness = 1.0;                   // many slabs, each of several ranges
  settings.slabPrecision = SlabPrecision::Float;  // see TinyBudgetStepsGiveRendersPicture
  Camera cam;
  cam.frame(s.volume.boundsMin(), s.volume.boundsMax(), {0.2, 0.3, 1.0}, {0, 1, 0}, 1.0);
  constexpr int kSize = 128;  // most slabs' rectangles: more than two bands of 32 rows
  r.render(cam, settings, kSize, kSize);
  const Image8 whole = r.readImage();
  const RenderStats wholeStats = r.stats();
  ASSERT_GT(wholeStats.slabEntries / wholeStats.slabsDrawn, 512u);  // ranges, then a finish
  r.beginFrame(cam, settings, kSize, kSize);
  RenderStats before = r.stats();
  double progress = 0.0;
  int steps = 0, drawingSteps = 0, both = 0, finishesAlone = 0, bandsAlone = 0;
  bool lastStepDrew = false;
  for (bool done = false; !done && steps < 100000; ++steps) {
    done = r.stepFrame(kTinyBudgetMs);
    const RenderStats now = r.stats();
    const bool drew = now.slabEntries > before.slabEntries;
    const bool finished = now.slabsDrawn > before.slabsDrawn;
    lastStepDrew = drew || finished;
    const bool passed = r.frameProgress() > progress;  // a band of a pass, at least
    // The first step that draws (after the partition's), before anything is measured, may
    // draw a whole slab.
    if (drawingSteps > 0 && drew && finished) ++both;
    if (finished && !drew) ++finishesAlone;
    if (passed && !drew && !finished) ++bandsAlone;
    drawingSteps += drew || finished;
    before = now;
    progress = r.frameProgress();
  }
  EXPECT_EQ(both, 0);
  // The final pass (over the whole picture) takes a step of its own where it does not fit
  // beside the last slab's close.
  EXPECT_FALSE(lastStepDrew);
  EXPECT_GE(finishesAlone, int(wholeStats.slabsDrawn) - 1);
  EXPECT_GE(bandsAlone, int(wholeStats.slabsDrawn) / 2) << finishesAlone;
  EXPECT_EQ(before.slabsDrawn, wholeStats.slabsDrawn);
  EXPECT_EQ(before.slabEntries, wholeStats.slabEntries);
  EXPECT_LE(maxDifference(r.readImage(), whole), 1);
}

// A new beginFrame abandons the frame under way: the next one starts clean.
TEST_F(ProgressiveFrame, AbandonedFrameLeavesNoTrace) {
  const SyntheticVolume s = makeSyntheticVolume("sphere:24");
  SplatRenderer& r = *renderer();
  r.setVolume(s.volume);
  r.setTransferFunction(*s.transferFunction);
  RenderSettings settings = rasterSettings();  // stepped slab by slab
  settings.slabThickness = 1.0;
  Camera a, b;
  a.frame(s.volume.boundsMin(), s.volume.boundsMax(), {0.0, 0.0, 1.0}, {0, 1, 0}, 1.0);
  b.frame(s.volume.boundsMin(), s.volume.boundsMax(), {0.6, 0.0, 1.0}, {0, 1, 0}, 1.0);
  r.render(b, settings, 64, 64);
  const Image8 whole = r.readImage();
  r.beginFrame(a, settings, 64, 64);
  for (int i = 0; i < 5; ++i) ASSERT_FALSE(r.stepFrame(kTinyBudgetMs));
  r.beginFrame(b, settings, 64, 64);
  while (!r.stepFrame(kTinyBudgetMs)) {
  }
  EXPECT_LE(maxDifference(r.readImage(), whole), 1);
}

// LodRenderer's full level stepped: the coarse picture stays last() until the frame is done.
TEST_F(ProgressiveFrame, LodRendererKeepsCoarseLevelUntilFullFrameIsDone) {
  LodScene scene("marschner-lobb:32");
  LodRenderer& lod = scene.lod;
  const Camera& cam = scene.camera;
  const RenderSettings settings = manySlabs();
  lod.render(0, cam, settings, 64, 64);
  const Image8 full = lod.last().readImage();
  lod.render(3, cam, settings, 64, 64);
  const unsigned coarseTexture = lod.outputTexture();
  ASSERT_EQ(lod.lastLevel(), 3);
  lod.beginFull(cam, settings, 64, 64);
  int steps = 0;
  while (!lod.stepFull(kTinyBudgetMs)) {
    ++steps;
    EXPECT_TRUE(lod.fullPending());
    EXPECT_EQ(lod.lastLevel(), 3);
    EXPECT_EQ(lod.outputTexture(), coarseTexture);
    EXPECT_LT(lod.fullProgress(), 1.0);
  }
  EXPECT_GT(steps, 10);
  EXPECT_FALSE(lod.fullPending());
  EXPECT_EQ(lod.lastLevel(), 0);
  EXPECT_EQ(lod.imageWidth(), 64);
  EXPECT_NE(lod.outputTexture(), coarseTexture);
  EXPECT_LE(maxDifference(lod.last().readImage(), full), 1);
}

// The full level's picture on screen and a full frame at another size (a capture larger than
// the window, a resized window): its images are made in steps too, one a step at a tiny budget,
// and the picture of the size before stays shown, until the frame is done.
TEST_F(ProgressiveFrame, AFullFrameAtANewSizeKeepsTheLastPictureShownWhileItsImagesAreMade) {
  LodScene scene("marschner-lobb:32");
  LodRenderer& lod = scene.lod;
  const Camera& cam = scene.camera;
  const RenderSettings settings = manySlabs();
  lod.render(0, cam, settings, 96, 80);
  const Image8 larger = lod.last().readImage();
  lod.render(0, cam, settings, 64, 48);
  const Image8 shown = lod.last().readImage();
  const unsigned shownTexture = lod.outputTexture();
  ASSERT_EQ(shown.width, 64);
  lod.beginFull(cam, settings, 96, 80);
  int steps = 0, setupSteps = 0;
  while (!lod.stepFull(kTinyBudgetMs)) {
    ++steps;
    if (lod.fullProgress() == 0.0) ++setupSteps;
    EXPECT_EQ(lod.outputTexture(), shownTexture) << "step " << steps;
    EXPECT_EQ(lod.imageWidth(), 64);
    if (steps % 5 == 1) {
      const Image8 now = lod.last().readImage();
      ASSERT_EQ(now.width, 64) << "step " << steps;
      EXPECT_EQ(maxDifference(now, shown), 0) << "step " << steps;
    }
    ASSERT_LT(steps, 100000);
  }
  // At least one step for each image the frame needs besides the first (slab, accumulation,
  // output, marks: four at the least), before anything is drawn.
  EXPECT_GE(setupSteps, 3);
  EXPECT_EQ(lod.imageWidth(), 96);
  EXPECT_EQ(lod.imageHeight(), 80);
  EXPECT_NE(lod.outputTexture(), 0u);
  EXPECT_LE(maxDifference(lod.last().readImage(), larger), 1);
}

// The window's scheduler: the budget is what the UI frame target leaves beside the rest of the
// frame (measured apart for frames that present), between 4 ms and the most it was given; a
// finished refinement reports its steps.
TEST_F(ProgressiveFrame, RefinementBudgetAdaptsAndReportsItsFrames) {
  LodScene scene("marschner-lobb:32");
  LodRenderer& lod = scene.lod;
  const Camera& cam = scene.camera;
  const RenderSettings settings = manySlabs();
  lod.render(0, cam, settings, 64, 64);
  const Image8 full = lod.last().readImage();
  lod.render(4, cam, settings, 64, 64);

  ProgressiveRefinement budgeted(30.0, 50.0);
  budgeted.start(lod, cam, settings, {64, 64});
  EXPECT_TRUE(budgeted.active());
  budgeted.reportFrame(budgeted.lastStepMs() + 35.0);  // 35 ms besides the step: 15 left
  EXPECT_NEAR(budgeted.budgetMs(false), 15.0, 1e-9);
  budgeted.reportFrame(budgeted.lastStepMs() + 100.0);  // over the target: the least
  EXPECT_NEAR(budgeted.budgetMs(false), 4.0, 1e-9);
  budgeted.reportFrame(budgeted.lastStepMs() + 1.0);  // never above the most it was given
  EXPECT_NEAR(budgeted.budgetMs(false), 30.0, 1e-9);
  // A frame that presents spends more besides its step: measured apart, for the frames that
  // will present.
  budgeted.notePresented();
  budgeted.reportFrame(budgeted.lastStepMs() + 40.0);
  EXPECT_NEAR(budgeted.budgetMs(true), 10.0, 1e-9);
  EXPECT_NEAR(budgeted.budgetMs(false), 30.0, 1e-9);
  budgeted.step(lod, true);
  EXPECT_NEAR(budgeted.budgetMs(), 10.0, 1e-9);        // the last step's
  budgeted.reportFrame(budgeted.lastStepMs() + 20.0);  // no present: the other kind
  EXPECT_NEAR(budgeted.budgetMs(true), 10.0, 1e-9);
  EXPECT_NEAR(budgeted.budgetMs(false), 30.0, 1e-9);
  // A GPU may have drawn the whole frame in that 10 ms step: begun again, the next step is one
  // (the budgets measured are kept).
  if (!budgeted.active()) budgeted.start(lod, cam, settings, {64, 64});
  budgeted.step(lod, false);
  EXPECT_NEAR(budgeted.budgetMs(), 30.0, 1e-9);
  budgeted.cancel();
  EXPECT_FALSE(budgeted.active());
  EXPECT_FALSE(budgeted.step(lod));

  // A budget no step can meet: many UI frames, each reported, the coarse level on screen.
  lod.render(4, cam, settings, 64, 64);  // a refinement above may have finished
  ProgressiveRefinement tiny(kTinyBudgetMs, 50.0);
  tiny.start(lod, cam, settings, {64, 64});
  int frames = 0;
  bool done = false;
  while (!done && frames < 100000) {
    done = tiny.step(lod);
    ++frames;
    tiny.reportFrame(tiny.lastStepMs() + 1.0);
    if (!done) {
      EXPECT_EQ(lod.lastLevel(), 4);
      EXPECT_LT(tiny.progress(lod), 1.0);
    }
  }
  EXPECT_GT(frames, 10);
  EXPECT_FALSE(tiny.active());
  EXPECT_EQ(tiny.last().frames, frames);
  EXPECT_EQ(tiny.last().index, 1);
  EXPECT_GE(tiny.last().wallMs, tiny.last().workMs * 0.99);
  EXPECT_GT(tiny.last().worstFrameMs, 0.0);
  EXPECT_EQ(lod.lastLevel(), 0);
  EXPECT_LE(maxDifference(lod.last().readImage(), full), 1);
}

// Frames that only step the refinement present the unchanged coarse picture again only after
// activity or once kPresentIntervalMs has passed since the last present; idle, always.
TEST_F(ProgressiveFrame, RefiningFramesPresentOnActivityOrAfterTheInterval) {
  LodScene scene("marschner-lobb:32");
  LodRenderer& lod = scene.lod;
  const Camera& cam = scene.camera;
  RenderSettings settings;
  lod.render(4, cam, settings, 64, 64);

  ProgressiveRefinement refinement(kTinyBudgetMs, 50.0);
  EXPECT_TRUE(refinement.presentsStep(false));  // nothing refining
  refinement.start(lod, cam, settings, {64, 64});
  refinement.notePresented();
  EXPECT_FALSE(refinement.presentsStep(false));
  EXPECT_TRUE(refinement.presentsStep(true));
  std::this_thread::sleep_for(
      std::chrono::duration<double, std::milli>(ProgressiveRefinement::kPresentIntervalMs));
  EXPECT_TRUE(refinement.presentsStep(false));
  refinement.notePresented();
  EXPECT_FALSE(refinement.presentsStep(false));
  // A step budgeted as not presenting keeps its frame from presenting when the interval passes
  // during it; the next frame presents.
  ASSERT_FALSE(refinement.step(lod, false));
  std::this_thread::sleep_for(
      std::chrono::duration<double, std::milli>(ProgressiveRefinement::kPresentIntervalMs));
  EXPECT_FALSE(refinement.presentsStep(false));
  EXPECT_TRUE(refinement.presentsStep(true));  // input in that frame: presented after all
  refinement.reportFrame(1.0);
  EXPECT_TRUE(refinement.presentsStep(false));
  ASSERT_FALSE(refinement.step(lod, true));
  EXPECT_TRUE(refinement.presentsStep(false));
  refinement.notePresented();
  refinement.reportFrame(1.0);
  EXPECT_FALSE(refinement.presentsStep(false));
  while (!refinement.step(lod)) {
  }
  EXPECT_TRUE(refinement.presentsStep(false));  // the finished picture
}

}  // namespace
}  // namespace ewa::test
