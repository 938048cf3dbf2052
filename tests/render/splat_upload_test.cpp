// Splat sets uploaded on a worker through a context of the renderer's share group: the picture
// of an upload on the drawing thread, put in place by a later call or by the next frame, dropped
// by a newer change; the coarse levels' warm-up the same way; a stepped frame's images of a new
// size made there too.
#include <chrono>
#include <limits>
#include <thread>

#include "core/async_splat_builder.h"
#include "image_compare.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class SplatUploadTest : public RenderFixture {
 protected:
  void SetUp() override {
    RenderFixture::SetUp();
    if (IsSkipped()) return;
    uploads_ = context()->createUploadContext();
    if (!uploads_) GTEST_SKIP() << context()->backendName() << " makes no upload context";
    renderer()->setPartition(PartitionMode::Cpu);  // pictures compared to the bit
    renderer()->setWorkerUploadBytes(0);           // every set on the worker
    renderer()->setUploadContext(uploads_.get());
    volume_ = makeVolume(14, 14, 14, glm::dvec3(1.0), [](int i, int j, int k) {
      return (i - 7) * (i - 7) + (j - 6) * (j - 6) + (k - 7) * (k - 7) < 30;
    });
    camera_.frame(volume_.boundsMin(), volume_.boundsMax(), {0.3, 0.4, 1.0}, {0, 1, 0}, 1.0);
  }
  void TearDown() override {
    if (!uploads_) return;
    // Nothing of this test left uploading through its context.
    renderer()->setVolume(volume_);
    EXPECT_FALSE(renderer()->uploadingSplats());
    renderer()->setWorkerUploadBytes(SplatRenderer::kWorkerUploadBytes);
    renderer()->setUploadContext(nullptr);
  }

  // The picture with the set classified and uploaded on this thread.
  Image8 direct(const TransferFunction& tf) {
    renderer()->setVolume(volume_);
    renderer()->setTransferFunction(tf);
    renderer()->render(camera_, settings_, kSize, kSize);
    return renderer()->readImage();
  }
  BuiltSplats built(const TransferFunction& tf) {
    AsyncSplatBuilder builder;
    builder.request(volume_, tf, splatClassification(settings_), renderer()->maxSplats());
    std::optional<BuiltSplats> set = builder.finish();
    EXPECT_TRUE(set.has_value());
    return std::move(*set);
  }
  // Polls takeUploadedSplats() as the window's frames do; false after a minute (a hang).
  static bool takeWhenUploaded() {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (!renderer()->takeUploadedSplats()) {
      if (std::chrono::steady_clock::now() > deadline) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
  }

  static constexpr int kSize = 48;
  std::unique_ptr<platform::UploadContext> uploads_;
  Volume volume_;
  Camera camera_;
  // Pre-classified: no pair table, so a frame's classifyMs is 0 unless it classifies.
  RenderSettings settings_ = paperSettings();
};

TEST_F(SplatUploadTest, AWorkerUploadDrawsThePictureOfAnUploadHere) {
  const TransferFunction tf = whiteTf(0.4, 1.0);
  const Image8 want = direct(tf);
  // A transparent function first: an empty set on screen while the worker uploads.
  renderer()->setTransferFunction(whiteTf(0.0, 1.0));
  renderer()->render(camera_, settings_, kSize, kSize);
  ASSERT_EQ(renderer()->splats().size(), 0u);
  renderer()->updateTransferTexture(tf);
  BuiltSplats set = built(tf);
  const size_t count = set.splats.splats.size();
  ASSERT_GT(count, 0u);
  EXPECT_FALSE(renderer()->beginSplats(std::move(set.splats), set.classification));
  EXPECT_TRUE(renderer()->uploadingSplats());
  EXPECT_FALSE(renderer()->needsSplats(set.classification));  // the upload brings it
  EXPECT_EQ(renderer()->splats().size(), 0u);                 // the set before, meanwhile
  ASSERT_TRUE(takeWhenUploaded());
  EXPECT_FALSE(renderer()->uploadingSplats());
  EXPECT_EQ(renderer()->splats().size(), count);
  renderer()->render(camera_, settings_, kSize, kSize);
  EXPECT_EQ(renderer()->stats().classifyMs, 0.0);
  EXPECT_EQ(renderer()->readImage().pixels, want.pixels);
}

TEST_F(SplatUploadTest, TheNextFrameTakesAnUploadUnderWay) {
  const TransferFunction tf = whiteTf(0.4, 1.0);
  const Image8 want = direct(tf);
  BuiltSplats set = built(tf);
  renderer()->setTransferFunction(whiteTf(0.2, 1.0));  // the set on screen goes stale
  renderer()->updateTransferTexture(tf);
  EXPECT_FALSE(renderer()->beginSplats(std::move(set.splats), set.classification));
  // No take: the frame waits for the upload instead of classifying the volume itself.
  renderer()->render(camera_, settings_, kSize, kSize);
  EXPECT_FALSE(renderer()->uploadingSplats());
  EXPECT_EQ(renderer()->stats().classifyMs, 0.0);
  EXPECT_EQ(renderer()->readImage().pixels, want.pixels);
}

TEST_F(SplatUploadTest, ANewFunctionOrSetDropsTheUpload) {
  const TransferFunction tf = whiteTf(0.4, 1.0);
  const TransferFunction other = whiteTf(0.1, 1.0);
  const Image8 wantOther = direct(other);
  BuiltSplats set = built(tf);
  EXPECT_FALSE(renderer()->beginSplats(std::move(set.splats), set.classification));
  renderer()->setTransferFunction(other);  // the upload's set is of the function before
  EXPECT_FALSE(renderer()->uploadingSplats());
  EXPECT_FALSE(renderer()->takeUploadedSplats());
  EXPECT_TRUE(renderer()->needsSplats(set.classification));
  renderer()->render(camera_, settings_, kSize, kSize);
  EXPECT_EQ(renderer()->readImage().pixels, wantOther.pixels);

  // A set given at once replaces one still uploading; a set under the threshold is set at once.
  BuiltSplats first = built(tf);
  BuiltSplats second = built(other);
  EXPECT_FALSE(renderer()->beginSplats(std::move(first.splats), first.classification));
  renderer()->setWorkerUploadBytes(SplatRenderer::kWorkerUploadBytes);
  EXPECT_TRUE(renderer()->beginSplats(std::move(second.splats), second.classification));
  EXPECT_FALSE(renderer()->uploadingSplats());
  renderer()->render(camera_, settings_, kSize, kSize);
  EXPECT_EQ(renderer()->readImage().pixels, wantOther.pixels);
}

TEST_F(SplatUploadTest, TwoUploadsAtOnceTakeTurnsOnTheContext) {
  // The full level's set and a coarse level's may be uploaded at the same time: their workers
  // bind the one context in turn.
  const TransferFunction tf = whiteTf(0.4, 1.0);
  const Image8 want = direct(tf);
  SplatRenderer second{gl::ShaderLibrary()};
  second.setPartition(PartitionMode::Cpu);
  second.setWorkerUploadBytes(0);
  second.setUploadContext(uploads_.get());
  second.setVolume(volume_);
  second.setTransferFunction(tf);
  second.render(camera_, settings_, kSize, kSize);
  const Image8 wantSecond = second.readImage();  // its own limits: not the fixture's
  BuiltSplats a = built(tf), b = built(tf);
  for (SplatRenderer* r : {renderer().get(), &second}) {
    r->setTransferFunction(whiteTf(0.2, 1.0));
    r->updateTransferTexture(tf);
  }
  EXPECT_FALSE(renderer()->beginSplats(std::move(a.splats), a.classification));
  EXPECT_FALSE(second.beginSplats(std::move(b.splats), b.classification));
  ASSERT_TRUE(takeWhenUploaded());
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (!second.takeUploadedSplats()) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  renderer()->render(camera_, settings_, kSize, kSize);
  second.render(camera_, settings_, kSize, kSize);
  EXPECT_EQ(second.stats().classifyMs, 0.0);
  EXPECT_EQ(renderer()->readImage().pixels, want.pixels);
  EXPECT_EQ(second.readImage().pixels, wantSecond.pixels);
}

TEST_F(SplatUploadTest, CoarseLevelsWarmUpThroughWorkerUploads) {
  LodScene s("marschner-lobb:32", uploads_.get());
  const RenderSettings settings = paperSettings();
  s.lod.render(s.lod.coarsestLevel(), s.camera, settings, 64, 64);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (s.lod.warmUpNext(s.camera, settings)) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  EXPECT_FALSE(s.lod.warmUpPending());
  // Every coarse level's set arrived through the worker: drawing it classifies nothing, and
  // draws what a cold renderer's own classification and upload draw.
  LodScene cold("marschner-lobb:32");
  for (int level = 1; level <= s.lod.coarsestLevel(); ++level) {
    s.lod.render(level, s.camera, settings, 64, 64);
    EXPECT_EQ(s.lod.last().stats().classifyMs, 0.0) << level;
    cold.lod.render(level, cold.camera, settings, 64, 64);
    EXPECT_LE(maxDifference(s.lod.last().readImage(), cold.lod.last().readImage()),
              kGpuPartitionLevels)
        << level;  // the GPU partition orders entries differently each frame
  }
}

// Steps prepare with a budget no image fits until the layout is ready; on this thread a step
// makes at most one image, so a step that returns with every image made had them from the
// worker. A fast worker may finish before the first step looks: that step is then the last.
int imagesFromTheWorker(RenderTargets& t, const TargetLayout& layout,
                        platform::UploadContext* uploads) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (!t.prepare(layout, 1e-6, uploads)) {
    EXPECT_EQ(t.imagesMade(), 0);  // nothing is made here while the worker works
    if (std::chrono::steady_clock::now() > deadline) {
      ADD_FAILURE() << "the worker made no images in a minute";
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return t.imagesMade();
}

TEST_F(SplatUploadTest, ANewSizesImagesAreMadeOnTheWorker) {
  RenderTargets t;
  const TargetLayout layout{40, 30, true, true, true, true, true};  // all nine images
  EXPECT_EQ(imagesFromTheWorker(t, layout, uploads_.get()), 9);
  EXPECT_TRUE(t.ready(layout));
  EXPECT_TRUE(t.slab && t.accum && t.output && t.stencil && t.slabOther && t.slabBack &&
              t.slabOtherBack && t.slabNormal && t.coarseMarks);
  // Another size asked for while the worker makes one (or after it made it): the new size's
  // images are what the next steps bring.
  const TargetLayout other{24, 20, true, false, false, true, false};
  const TargetLayout third{32, 16, true, false, false, true, false};
  t.prepare(other, 1e-6, uploads_.get());
  EXPECT_EQ(imagesFromTheWorker(t, third, uploads_.get()), 5);  // slab, accumulation, output,
                                                                // stencil, the second slab
  EXPECT_TRUE(t.ready(third));
  EXPECT_EQ(t.width, 32);
  // A whole frame's prepare while a job is under way for its layout takes the job's images.
  if (!t.prepare(other, 1e-6, uploads_.get())) {
    EXPECT_TRUE(t.prepare(other, std::numeric_limits<double>::infinity()));
  }
  EXPECT_EQ(t.imagesMade(), 5);
  EXPECT_TRUE(t.ready(other));
}

TEST_F(SplatUploadTest, AFrameAtANewSizeDrawsWithImagesMadeOnTheWorker) {
  LodScene scene("marschner-lobb:32", uploads_.get());
  LodRenderer& lod = scene.lod;
  const RenderSettings settings = rasterSettings();
  lod.render(0, scene.camera, settings, 96, 80);  // whole frames: images made here
  const Image8 larger = lod.last().readImage();
  lod.render(0, scene.camera, settings, 64, 48);
  const unsigned shownTexture = lod.outputTexture();
  lod.beginFull(scene.camera, settings, 96, 80);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (!lod.stepFull(1e-6)) {
    // The picture of the size before stays shown while the worker makes the new images.
    if (lod.fullProgress() == 0.0) {
      EXPECT_EQ(lod.outputTexture(), shownTexture);
    }
    ASSERT_LT(std::chrono::steady_clock::now(), deadline);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  EXPECT_EQ(lod.imageWidth(), 96);
  EXPECT_LE(maxDifference(lod.last().readImage(), larger), 1);
}

TEST_F(SplatUploadTest, AMovingLevelsImagesOfANewSizeAreMadeAhead) {
  LodScene scene("marschner-lobb:32", uploads_.get());
  LodRenderer& lod = scene.lod;
  const RenderSettings settings = rasterSettings();
  const int level = 3;  // volume/4, image/2
  lod.render(level, scene.camera, settings, 64, 48);
  EXPECT_TRUE(lod.prepareImages(level, settings, 64, 48, 0.0));  // there: nothing to make
  // A new size: the worker makes the images, a call with no time to wait returns at once (with
  // them only where the worker was quicker than the call's look).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (!lod.prepareImages(level, settings, 128, 96, 1e-6)) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  EXPECT_TRUE(lod.prepareImages(level, settings, 128, 96, 0.0));
  // The level drawn into them draws what a renderer that made its own draws.
  lod.render(level, scene.camera, settings, 128, 96);
  EXPECT_EQ(lod.imageWidth(), 64);
  LodScene cold("marschner-lobb:32");
  cold.lod.render(level, cold.camera, settings, 128, 96);
  EXPECT_LE(maxDifference(lod.last().readImage(), cold.lod.last().readImage()), 1);
  // The full level's images for another size abandon its frame under way, as its render does.
  lod.beginFull(scene.camera, settings, 64, 48);
  ASSERT_TRUE(lod.fullPending());
  lod.prepareImages(1, settings, 96, 80, std::numeric_limits<double>::infinity());  // volume/2
  EXPECT_TRUE(lod.fullPending());
  EXPECT_TRUE(lod.prepareImages(0, settings, 96, 80, std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(lod.fullPending());
  lod.render(0, scene.camera, settings, 96, 80);
  EXPECT_EQ(lod.imageWidth(), 96);
}

}  // namespace
}  // namespace ewa::test
