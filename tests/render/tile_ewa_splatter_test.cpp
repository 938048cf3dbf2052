// The benchmarks' compute EWA splatter against the rasterizer: the same pre-classified picture
// from the same footprints and slab lists, for both tile sizes, with translucent haze behind an
// opaque wall (early termination), a perspective view and kernels across tile and slab borders.
#include "render/tile_ewa_splatter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bench/bench_tile_ewa.h"
#include "cli_run.h"
#include "core/ewa_footprint.h"
#include "core/slab_partition.h"
#include "gl/gl_error.h"
#include "image_compare.h"
#include "io/png_io.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

// A dense wall over the left half at the front, faint haze behind it over the whole view.
Volume wallAndHaze() {
  const int n = 24;
  std::vector<uint8_t> bytes(size_t(n) * n * n, 0);
  for (int k = 0; k < n; ++k)
    for (int j = 2; j < n - 2; ++j)
      for (int i = 2; i < n - 2; ++i) {
        uint8_t v = 0;
        if (k >= 16 && k <= 20 && i < n / 2) v = 250;
        if (k >= 2 && k <= 13) v = uint8_t(60 + 4 * ((i + j + k) % 8));
        bytes[i + n * (j + size_t(n) * k)] = v;
      }
  return Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, std::move(bytes));
}

TransferFunction wallTf() {
  TransferFunction tf;
  tf.opacity = {{30.0, 0.0}, {60.0, 0.04}, {100.0, 0.08}, {240.0, 1.0}, {255.0, 1.0}};
  tf.color = {{0.0, {0.2, 0.5, 1.0}}, {100.0, {0.3, 0.9, 0.4}}, {255.0, {1.0, 0.8, 0.3}}};
  return tf;
}

class TileEwaSplatterTest : public RenderFixture {
 protected:
  const Volume vol = wallAndHaze();
  const TransferFunction tf = wallTf();

  // The renderer with the wall and haze, its slab lists made by `partition`.
  SplatRenderer& wallRenderer(PartitionMode partition) {
    SplatRenderer& r = *renderer();
    r.setVolume(vol);
    r.setTransferFunction(tf);
    r.setPartition(partition);
    return r;
  }
  // Default settings as the compute tiles draw them, rasterized for the comparisons: slab images
  // at the picture's pixels, no culling, one pass a slab.
  static RenderSettings tileSettings() {
    RenderSettings settings = rasterSettings();
    settings.coarseSlabs = false;
    settings.occlusionCulling = OcclusionCulling::Off;
    settings.slabPasses = 1;
    return settings;
  }
  // Oblique: footprints straddle the wall's edge.
  static Camera obliqueCamera() {
    Camera cam;
    cam.focalPoint = {11.5, 11.5, 11.5};
    cam.position = {17.0, 14.0, 62.0};
    cam.viewAngleDeg = 30.0;
    return cam;
  }
};

TEST_F(TileEwaSplatterTest, DrawsTheRasterizersPreClassifiedPicture) {
  wallRenderer(PartitionMode::Cpu);
  RenderSettings settings = tileSettings();  // today's kernels (0.7 wide, cutoff 5)
  settings.classification.mode = ClassificationMode::Pre;
  const Camera cam = obliqueCamera();
  const int width = 61, height = 53;  // not multiples of either tile size
  // Without early termination and with it: the rasterizer marks opaque pixels every few slabs,
  // the tiles stop a pixel at the first slab past the threshold. Measured: 1 and 3 levels at
  // most (without the depth split: 63).
  for (const auto& [termination, tolerance] : {std::pair{1.0, 2}, std::pair{0.99, 4}}) {
    SCOPED_TRACE(termination);
    settings.terminationOpacity = termination;
    renderer()->render(cam, settings, width, height);
    const Image8 raster = renderer()->readImage();
    ASSERT_GT(renderer()->stats().slabs, 10u) << "a frame of many slabs";
    const TileEwaFrame frame = tileEwaFrame(*renderer(), vol, tf, cam, settings, width, height);
    ASSERT_FALSE(frame.entries.empty());
    for (int tileSize : {8, 16}) {
      SCOPED_TRACE(tileSize);
      TileEwaSplatter splatter(gl::ShaderLibrary(), tileSize);
      splatter.setFrame(frame);
      splatter.draw(20, 17);  // a smaller picture first: the buffers then grow
      const TileEwaSplatter::Timing t = splatter.draw(width, height);
      EXPECT_GT(t.entries, frame.entries.size() / 2);
      const std::vector<glm::vec4> picture = splatter.picture();
      ASSERT_EQ(picture.size(), size_t(width * height));
      const Image8 tiles = tileEwaImage(picture, width, height, settings.background);
      int opaque = 0;
      for (const glm::vec4& p : picture) opaque += p.a > 0.98f;
      // The transfer function's texture against its C++ values and the sums' order differ.
      const int worst = maxDifference(tiles, raster);
      EXPECT_LE(worst, tolerance);
      EXPECT_GT(meanValue(raster), 30.0) << "the picture should not be empty";
      EXPECT_GT(opaque, width * height / 10) << "the wall should stop some pixels";
      if (worst > tolerance) {
        const std::string out = testOutputDir() + "/tile_ewa_" + std::to_string(tileSize);
        writePng(out + ".actual.png", tiles);
        writePng(out + ".raster.png", raster);
        ADD_FAILURE() << "pictures written to " << out << ".{actual,raster}.png";
      }
    }
  }
}

// The records the GPU makes from the renderer's own setup (SplatRenderer::writeTileSplats) are
// the CPU's (tileEwaFrame) within float rounding and the transfer function's texture, splat
// for splat, and draw the rasterizer's picture as closely as they do.
TEST_F(TileEwaSplatterTest, GpuRecordsAreTheCpuFootprintsAndDrawTheSamePicture) {
  SplatRenderer& r = wallRenderer(PartitionMode::Cpu);
  RenderSettings settings = tileSettings();
  settings.classification.mode = ClassificationMode::Pre;
  settings.terminationOpacity = 1.0;
  Camera cam;
  cam.focalPoint = {11.5, 11.5, 11.5};
  cam.position = {-6.0, 8.0, 22.0};  // perspective, near: many kernels lie outside the view
  cam.viewAngleDeg = 25.0;
  const int width = 57, height = 49;
  r.render(cam, settings, width, height);
  const Image8 raster = r.readImage();
  const TileEwaFrame frame = tileEwaFrame(r, vol, tf, cam, settings, width, height);
  TileEwaSplatter splatter(gl::ShaderLibrary(), 8);
  splatter.setFrame(frame);
  r.writeTileSplats(splatter.splatBuffer());
  std::vector<TileEwaSplat> gpu(frame.splats.size());
  splatter.splatBuffer().getSubData(0, GLsizeiptr(gpu.size() * sizeof(TileEwaSplat)), gpu.data());
  const auto near = [](const glm::vec4& a, const glm::vec4& b, float relative, float absolute) {
    for (int c = 0; c < 4; ++c)
      if (!(std::abs(a[c] - b[c]) <=
            absolute + relative * std::max(std::abs(a[c]), std::abs(b[c]))))
        return false;
    return true;
  };
  // The CPU's footprints skip no kernel outside the view; the GPU's culls them (cullKernel),
  // which reach no tile.
  const auto reaches = [&](const glm::vec4& box) {
    return box.x + box.z > 0.0f && box.x - box.z < float(width) && box.y + box.w > 0.0f &&
           box.y - box.w < float(height);
  };
  size_t gpuDrawn = 0, cpuDrawn = 0, mismatched = 0;
  for (size_t n = 0; n < gpu.size(); ++n) {
    const TileEwaSplat& g = gpu[n];
    const TileEwaSplat& c = frame.splats[n];
    const bool onGpu = g.conic.w > 0.0f, onCpu = c.conic.w > 0.0f;
    gpuDrawn += onGpu;
    cpuDrawn += onCpu;
    const bool same = near(g.box, c.box, 1e-4f, 1e-3f) && near(g.conic, c.conic, 2e-2f, 1e-6f) &&
                      near(g.depth, c.depth, 1e-4f, 1e-4f) && near(g.color, c.color, 2e-2f, 1e-3f);
    const bool fine = onGpu ? onCpu && same : !onCpu || !reaches(c.box);
    if (!fine && ++mismatched <= 5) {
      ADD_FAILURE() << "splat " << n << ": gpu box (" << g.box.x << ", " << g.box.y << ", "
                    << g.box.z << ", " << g.box.w << ") amplitude " << g.conic.w << ", cpu box ("
                    << c.box.x << ", " << c.box.y << ", " << c.box.z << ", " << c.box.w
                    << ") amplitude " << c.conic.w;
    }
  }
  EXPECT_EQ(mismatched, 0u);
  EXPECT_GT(gpuDrawn, cpuDrawn / 4);
  EXPECT_LT(gpuDrawn, cpuDrawn) << "the near view should leave some kernels out";
  splatter.draw(width, height);
  const Image8 tiles = tileEwaImage(splatter.picture(), width, height, settings.background);
  EXPECT_GT(meanValue(raster), 20.0);
  EXPECT_LE(maxDifference(tiles, raster), 2);
}

// The default frame (post-classified, pre-integrated in quarters of a slab), unshaded and shaded
// with ray normals (the default) and from the field's gradient, composited by the tiles from the
// renderer's own records, slab lists and classification state, is the rasterizer's: with
// translucent haze behind the wall, so segments, neighbouring slabs, normals across tile borders
// and early termination all count.
TEST_F(TileEwaSplatterTest, DrawsTheRasterizersPostClassifiedPicture) {
  SplatRenderer& r = wallRenderer(PartitionMode::Cpu);
  RenderSettings settings = tileSettings();  // the default classification
  const Camera cam = obliqueCamera();
  const int width = 61, height = 53;
  // Measured: 1 level at most without early termination, 3 with it (the rasterizer marks
  // opaque pixels every few slabs, the tiles stop a pixel at once).
  for (const auto& [termination, tolerance, shaded, normals] :
       {std::tuple{1.0, 2, true, PostNormals::Ray}, std::tuple{0.99, 4, true, PostNormals::Ray},
        std::tuple{0.99, 4, true, PostNormals::Field},
        std::tuple{0.99, 4, false, PostNormals::Ray}}) {
    SCOPED_TRACE(std::to_string(termination) + (shaded ? " shaded, " : " unshaded, ") +
                 postNormalsName(normals));
    settings.terminationOpacity = termination;
    settings.lighting.enabled = shaded;
    settings.postNormals = normals;
    r.render(cam, settings, width, height);
    const Image8 raster = r.readImage();
    bool post = false, shading = false;
    ASSERT_TRUE(r.tileComposite(post, shading));
    EXPECT_TRUE(post);
    EXPECT_EQ(shading, shaded);
    for (int tileSize : {8, 16}) {
      SCOPED_TRACE(tileSize);
      TileEwaSplatter splatter(gl::ShaderLibrary(), tileSize);
      ASSERT_TRUE(r.loadTiles(splatter));
      splatter.draw(width, height);
      const Image8 tiles = tileEwaImage(splatter.picture(), width, height, settings.background);
      const int worst = maxDifference(tiles, raster);
      EXPECT_LE(worst, tolerance);
      EXPECT_GT(meanValue(raster), 30.0) << "the picture should not be empty";
      // In runs of a few slabs (each dispatch taking the picture and the last slab's sums from
      // the one before): the same picture.
      splatter.setChunkIterations(300);
      EXPECT_GT(splatter.draw(width, height).chunks, 3u);
      EXPECT_LE(maxDifference(tileEwaImage(splatter.picture(), width, height, settings.background),
                              tiles),
                1);
      if (worst > tolerance) {
        const std::string out = testOutputDir() + "/tile_ewa_post_" + std::to_string(tileSize) +
                                (shaded ? std::string("_shaded_") + postNormalsName(normals) : "");
        writePng(out + ".actual.png", tiles);
        writePng(out + ".raster.png", raster);
        ADD_FAILURE() << "pictures written to " << out << ".{actual,raster}.png";
      }
    }
  }
  // Normals from the splats' own and halves of a slab are not drawn in tiles.
  bool post = false, shading = false;
  settings.lighting.enabled = true;
  settings.postNormals = PostNormals::Voxel;
  r.render(cam, settings, width, height);
  EXPECT_FALSE(r.tileComposite(post, shading));
  settings.postNormals = PostNormals::Field;
  settings.slabSamples = 2;
  r.render(cam, settings, width, height);
  EXPECT_FALSE(r.tileComposite(post, shading));
}

// The GPU partition's lists binned where they are (no list from the CPU) give the rasterizer's
// picture, pre- and post-classified.
TEST_F(TileEwaSplatterTest, BinsTheGpuPartitionsLists) {
  SplatRenderer& r = wallRenderer(PartitionMode::Gpu);
  RenderSettings settings = tileSettings();
  settings.terminationOpacity = 1.0;
  const Camera cam = obliqueCamera();
  const int width = 61, height = 53;
  for (ClassificationMode mode : {ClassificationMode::Pre, ClassificationMode::Post}) {
    SCOPED_TRACE(int(mode));
    settings.classification.mode = mode;
    r.render(cam, settings, width, height);
    const Image8 raster = r.readImage();
    ASSERT_NE(r.gpuSlabLists(), nullptr) << "the frame's lists were built on the GPU";
    TileEwaSplatter splatter(gl::ShaderLibrary(), 16);
    ASSERT_TRUE(r.loadTiles(splatter));  // no splats, entries or slabs from the CPU
    const TileEwaSplatter::Timing t = splatter.draw(width, height);
    EXPECT_GT(t.entries, r.gpuSlabLists()->entryCount() / 2);
    const Image8 tiles = tileEwaImage(splatter.picture(), width, height, settings.background);
    EXPECT_GT(meanValue(raster), 30.0);
    // Measured on llvmpipe: 1 level (a slab's first entry counted in the slab before: 3);
    // hardware GL fuses and orders the sums its own way.
    EXPECT_LE(maxDifference(tiles, raster), r.softwareGl() ? 1 : 2);
  }
}

// RenderSettings::splatter: whole frames drawn in tiles by the renderer itself are the
// rasterized frames (pre-classified and post-classified shaded, early termination, either
// partition, cropped and cut by a tilted plane), with the same slab entries; back-to-front
// frames and budgeted steps stay rasterized.
TEST_F(TileEwaSplatterTest, RendererDrawsWholeFramesInTilesWhenAsked) {
  const Camera cam = obliqueCamera();
  const int width = 61, height = 53;
  for (PartitionMode partition : {PartitionMode::Cpu, PartitionMode::Gpu}) {
    SplatRenderer& r = wallRenderer(partition);
    for (ClassificationMode mode : {ClassificationMode::Pre, ClassificationMode::Post}) {
      SCOPED_TRACE(std::to_string(int(partition)) + " " + std::to_string(int(mode)));
      RenderSettings settings = tileSettings();
      settings.classification.mode = mode;
      settings.lighting.enabled = mode == ClassificationMode::Post;
      r.render(cam, settings, width, height);
      const Image8 raster = r.readImage();
      const RenderStats rasterStats = r.stats();
      EXPECT_FALSE(rasterStats.tiles);
      settings.splatter = Splatter::Tiles;
      r.render(cam, settings, width, height);
      EXPECT_TRUE(r.stats().tiles);
      EXPECT_EQ(r.stats().slabEntries, rasterStats.slabEntries);
      EXPECT_GT(r.stats().splatMs, 0.0);
      const Image8 tiles = r.readImage();
      EXPECT_GT(meanValue(raster), 30.0);
      // Early termination on (0.99): 3 levels measured against the CPU lists (as above).
      EXPECT_LE(maxDifference(tiles, raster), 4);
    }
  }
  SplatRenderer& r = wallRenderer(PartitionMode::Cpu);
  for (ClassificationMode mode : {ClassificationMode::Pre, ClassificationMode::Post}) {
    SCOPED_TRACE("clipped " + std::to_string(int(mode)));
    RenderSettings settings = tileSettings();
    settings.classification.mode = mode;
    // The wall's left part cropped away, the haze cut by a tilted plane.
    settings.clip.cropEnabled = true;
    settings.clip.cropMin = {4.3, 0.0, 0.0};
    settings.clip.cropMax = {23.0, 23.0, 23.0};
    settings.clip.planes.push_back(ClipPlane{{11.5, 11.5, 8.0}, {0.3, 0.2, 1.0}, true});
    r.render(cam, settings, width, height);
    const Image8 raster = r.readImage();
    settings.splatter = Splatter::Tiles;
    r.render(cam, settings, width, height);
    EXPECT_TRUE(r.stats().tiles);
    const Image8 tiles = r.readImage();
    settings.clip = ClipRegion{};
    r.render(cam, settings, width, height);
    EXPECT_GT(maxDifference(r.readImage(), tiles), 40) << "the clip region should show";
    EXPECT_LE(maxDifference(tiles, raster), 4);
  }
  RenderSettings settings = tileSettings();
  settings.splatter = Splatter::Tiles;
  settings.order = CompositeOrder::BackToFront;
  r.render(cam, settings, width, height);
  EXPECT_FALSE(r.stats().tiles) << "back-to-front frames are rasterized";
  settings.order = CompositeOrder::FrontToBack;
  r.beginFrame(cam, settings, width, height);
  while (!r.stepFrame(5.0)) {
  }
  EXPECT_FALSE(r.stats().tiles) << "budgeted steps are rasterized";
}

// While it lives, `r` chooses as on a GPU: auto's choice between the rasterizer and the tiles,
// not the CPU splatter it takes on a software rasterizer.
class AsIfOnAGpu {
 public:
  explicit AsIfOnAGpu(SplatRenderer& r) : r_(r), software_(r.softwareGl()) {
    r_.setSoftwareRasterizer(false);
  }
  ~AsIfOnAGpu() { r_.setSoftwareRasterizer(software_); }
  AsIfOnAGpu(const AsIfOnAGpu&) = delete;
  AsIfOnAGpu& operator=(const AsIfOnAGpu&) = delete;

 private:
  SplatRenderer& r_;
  bool software_;
};

// RenderSettings::splatter auto (the default): rasterized where the GPU's timers are not used
// (software rasterizers); where they are, the first timed frame is rasterized, the next drawn in
// tiles, and the third the way whose splat stage took less. A frame in tiles does not count for
// auto passes a slab: the rasterized frame after it tries the second pass. Every picture the
// rasterizer's within the tiles' levels. Volumes of more splats than its limit stay rasterized.
TEST_F(TileEwaSplatterTest, AutoSplatterTriesBothThenTakesTheFaster) {
  const Camera cam = obliqueCamera();
  const int width = 61, height = 53;
  SplatRenderer& r = wallRenderer(PartitionMode::Cpu);
  const bool timers = r.gpuTimers();
  RenderSettings settings = tileSettings();
  settings.splatter = Splatter::Auto;
  settings.slabPasses = 0;
  settings.lighting.enabled = true;  // post-classified and shaded from the field
  const AsIfOnAGpu gpu(r);
  r.setGpuTimers(false);
  r.render(cam, settings, width, height);
  EXPECT_FALSE(r.stats().tiles);
  EXPECT_EQ(r.stats().slabPasses, 1);
  const Image8 raster = r.readImage();
  EXPECT_GT(meanValue(raster), 30.0);
  RenderSettings tiles = settings;
  tiles.splatter = Splatter::Tiles;
  r.render(cam, tiles, width, height);  // the tiles' programs and buffers made: counted below
  r.setGpuTimers(true);
  r.setVolume(vol);  // a volume set again: both ways timed afresh
  std::vector<RenderStats> frames;
  for (int i = 0; i < 3; ++i) {
    r.render(cam, settings, width, height);
    frames.push_back(r.stats());
    EXPECT_LE(maxDifference(r.readImage(), raster), 4) << "frame " << i;
    EXPECT_EQ(frames.back().note, "");
  }
  r.setGpuTimers(timers);
  // The tiles first (a single picture on a GPU takes them), then the rasterizer.
  EXPECT_TRUE(frames[0].tiles);
  EXPECT_EQ(frames[0].slabPasses, 0) << "tiles take no splat passes";
  EXPECT_FALSE(frames[1].tiles);
  EXPECT_EQ(frames[1].slabPasses, 1);
  ASSERT_GT(frames[0].splatMs, 0.0);
  ASSERT_GT(frames[1].splatMs, 0.0);
  ASSERT_EQ(frames[0].slabEntries, frames[1].slabEntries);
  EXPECT_EQ(frames[2].tiles, frames[0].splatMs < frames[1].splatMs);
  if (!frames[2].tiles) {
    EXPECT_EQ(frames[2].slabPasses, 2) << "the tiles' frame was counted";
  }
  // A renderer's first tile frame (its programs compiled, its splatter made) is not counted:
  // the next frame tries the tiles again, then the rasterizer.
  {
    SplatRenderer fresh{gl::ShaderLibrary()};
    const AsIfOnAGpu freshGpu(fresh);
    fresh.setPartition(PartitionMode::Cpu);
    fresh.setVolume(vol);
    fresh.setTransferFunction(tf);
    fresh.setGpuTimers(true);
    std::vector<bool> drewTiles;
    for (int i = 0; i < 3; ++i) {
      fresh.render(cam, settings, width, height);
      drewTiles.push_back(fresh.stats().tiles);
      if (i == 0) {
        EXPECT_LT(fresh.splatterTuner().cost(1), 0.0) << "the first use counted";
      }
    }
    EXPECT_EQ(drewTiles, (std::vector<bool>{true, true, false}));
    EXPECT_GT(fresh.splatterTuner().cost(1), 0.0);
    EXPECT_GT(fresh.splatterTuner().cost(0), 0.0);
  }
  // A volume of more splats than auto's limit stays rasterized (the tiles' memory).
  r.setGpuTimers(true);
  r.setAutoTileSplats(r.splats().size() - 1);
  r.setVolume(vol);
  for (int i = 0; i < 3; ++i) {
    r.render(cam, settings, width, height);
    EXPECT_FALSE(r.stats().tiles) << "frame " << i << " of a volume over the limit";
  }
  r.setAutoTileSplats(SplatRenderer::kAutoTileSplats);
  r.setGpuTimers(timers);
}

// The window's refinement under auto (budgeted steps): where the GPU's timers are used, its
// first frame is drawn whole in tiles in one step, the next rasterized in steps, and both costs
// count for the choice as whole frames' do. A budgeted frame stays rasterized where the tiles'
// last cost a slab entry would make the step longer than the limit, and when tiles are asked
// for outright (a whole frame is drawn in them then). Every picture the rasterizer's within the
// tiles' levels, from either partition's lists.
TEST_F(TileEwaSplatterTest, AutoSplatterDrawsBudgetedFramesInTilesWhereTheyFit) {
  const Camera cam = obliqueCamera();
  const int width = 61, height = 53;
  for (const PartitionMode partition : {PartitionMode::Cpu, PartitionMode::Gpu}) {
    SCOPED_TRACE(int(partition));
    SplatRenderer& r = wallRenderer(partition);
    const bool timers = r.gpuTimers();
    RenderSettings settings = tileSettings();
    settings.splatter = Splatter::Auto;
    settings.lighting.enabled = true;  // post-classified and shaded from the field
    const AsIfOnAGpu gpu(r);
    r.setGpuTimers(false);
    r.render(cam, settings, width, height);
    const Image8 raster = r.readImage();
    RenderSettings warmUp = settings;
    warmUp.splatter = Splatter::Tiles;
    r.render(cam, warmUp, width, height);  // the tiles' first use (not counted) before the timing
    r.setGpuTimers(true);
    r.setVolume(vol);  // both ways timed afresh
    // Steps of a microsecond: a chunk of slabs each. Returns the steps that drew (the last,
    // and those before it that left part of the frame drawn; the CPU partition's worker and the
    // upload of its lists take steps of their own).
    const auto budgeted = [&](const RenderSettings& s) {
      r.beginFrame(cam, s, width, height);
      int drawing = 1;
      while (!r.stepFrame(0.001)) drawing += r.frameProgress() > 0.0;
      EXPECT_LE(maxDifference(r.readImage(), raster), 4);
      return drawing;
    };
    EXPECT_EQ(budgeted(settings), 1) << "the tiles tried first, whole";
    EXPECT_TRUE(r.stats().tiles);
    const double tileCost = r.splatterTuner().cost(1);
    EXPECT_GT(tileCost, 0.0);
    EXPECT_GT(budgeted(settings), 2);
    EXPECT_FALSE(r.stats().tiles);
    EXPECT_GT(r.splatterTuner().cost(0), 0.0) << "the budgeted frame's cost counts";
    // Tiles the cheaper (as on a GPU): drawn whole while their frame fits the step limit.
    r.splatterTuner().report(1, r.splatterTuner().cost(0) * 0.1);
    EXPECT_EQ(budgeted(settings), 1);
    EXPECT_TRUE(r.stats().tiles);
    r.splatterTuner().report(1, r.splatterTuner().cost(0) * 0.1);
    r.setTileStepMs(0.0);  // no frame fits
    EXPECT_GT(budgeted(settings), 2);
    EXPECT_FALSE(r.stats().tiles);
    r.setTileStepMs(SplatRenderer::kTileStepMs);
    RenderSettings tiles = settings;
    tiles.splatter = Splatter::Tiles;
    EXPECT_GT(budgeted(tiles), 2);
    EXPECT_FALSE(r.stats().tiles) << "tiles asked for: whole frames only";
    r.render(cam, tiles, width, height);
    EXPECT_TRUE(r.stats().tiles);
    r.setGpuTimers(timers);
  }
}

// The tiles read their splats' records (64 bytes each) as one storage block: where the GL's
// block cannot hold them (a 512^3 volume's 4.8 GB on an H200), a frame asked for in tiles is
// rasterized with a note, and auto does not choose them.
TEST_F(TileEwaSplatterTest, RecordsBeyondAStorageBlockAreRasterized) {
  SplatRenderer& r = wallRenderer(PartitionMode::Cpu);
  const bool timers = r.gpuTimers();
  RenderSettings settings = tileSettings();
  const Camera cam = obliqueCamera();
  r.render(cam, settings, 40, 32);
  const Image8 raster = r.readImage();
  settings.splatter = Splatter::Tiles;
  r.render(cam, settings, 40, 32);
  EXPECT_TRUE(r.stats().tiles);
  EXPECT_EQ(r.stats().note, "");
  // A block that holds the splats the rasterizer reads but not the tiles' records.
  r.setStorageBlockLimit(r.splats().size() * sizeof(TileEwaSplat) - 1);
  r.render(cam, settings, 40, 32);
  EXPECT_FALSE(r.stats().tiles);
  EXPECT_FALSE(r.texelBuffers());
  EXPECT_NE(r.stats().note.find("exceed the GL's storage block"), std::string::npos)
      << r.stats().note;
  EXPECT_EQ(r.readImage().pixels, raster.pixels);
  settings.splatter = Splatter::Auto;
  r.setGpuTimers(true);  // where auto would try the tiles first
  r.render(cam, settings, 40, 32);
  EXPECT_FALSE(r.stats().tiles);
  r.setGpuTimers(timers);
  r.setStorageBlockLimit(0);
}

// Auto on a GL whose compiler rejects the tiles' programs: the first frame, which tries them, is
// rasterized instead and the statistics say why in one line from then on; asked for tiles
// outright, the error is thrown.
TEST_F(TileEwaSplatterTest, AutoSplatterRasterizesWhereTheTilesDoNotBuild) {
  const std::filesystem::path dir = std::filesystem::path(testOutputDir()) / "tiles_broken";
  std::filesystem::remove_all(dir);
  const std::filesystem::path shaders =
      brokenShaders(dir, "tile_ewa_post.comp.glsl", "void main", "int broken = ;\nvoid main");
  SplatRenderer r{gl::ShaderLibrary(shaders.string())};
  r.setPartition(PartitionMode::Cpu);  // one order of sums: the same picture to the bit
  r.setVolume(vol);
  r.setTransferFunction(tf);
  r.setGpuTimers(true);
  r.setSoftwareRasterizer(false);  // auto as on a GPU: tiles or rasterized, not the CPU
  const Camera cam = obliqueCamera();
  RenderSettings settings = tileSettings();
  settings.splatter = Splatter::Auto;
  std::vector<RenderStats> frames;
  for (int i = 0; i < 3; ++i) {
    r.render(cam, settings, 40, 36);
    frames.push_back(r.stats());
    EXPECT_FALSE(frames.back().tiles) << "frame " << i;
  }
  // The first frame tries the tiles (auto's first way on a GPU) and is rasterized instead.
  EXPECT_EQ(frames[0].note.find("compute tiles unavailable, frames rasterized: "), 0u)
      << frames[0].note;
  EXPECT_NE(frames[0].note.find("tile_ewa_post.comp.glsl"), std::string::npos) << frames[0].note;
  EXPECT_EQ(lineCount(frames[0].note), 0);
  EXPECT_EQ(frames[1].note, frames[0].note);
  EXPECT_EQ(frames[2].note, frames[0].note);
  const Image8 rasterized = r.readImage();
  settings.splatter = Splatter::Raster;
  r.render(cam, settings, 40, 36);
  EXPECT_EQ(maxDifference(r.readImage(), rasterized), 0);
  settings.splatter = Splatter::Tiles;
  EXPECT_THROW(r.render(cam, settings, 40, 36), gl::GlError);
}

// Seventy thousand faint splats over one tile in one slab: every one is added (llvmpipe ends a
// shader's loops after 65535 iterations in all, which one splat an iteration would reach; the
// picture was then a few SIMD rows short), checked against the closed form.
TEST_F(TileEwaSplatterTest, AddsEverySplatOfABusyTile) {
  const int count = 70000, size = 16;
  const float amplitude = 2e-5f, cutoff = 5.0f;
  TileEwaFrame frame;
  frame.cutoff = cutoff;
  frame.termination = 1.0f;
  frame.slabDepths = {glm::vec2(9.0f, 11.0f)};
  TileEwaSplat splat;
  splat.box = glm::vec4(8.0f, 8.0f, 20.0f, 20.0f);         // covers the picture
  splat.conic = glm::vec4(0.01f, 0.0f, 0.01f, amplitude);  // variance 100 pixels^2
  splat.depth = glm::vec4(10.0f, 0.0f, 0.0f, 0.5f);
  splat.color = glm::vec4(1.0f, 0.5f, 0.25f, 0.0f);
  frame.splats.assign(size_t(count), splat);
  for (uint32_t n = 0; n < uint32_t(count); ++n)
    frame.entries.emplace_back(n | SlabPartition::kFirstSlab | SlabPartition::kLastSlab, 0u);
  for (int tileSize : {8, 16}) {
    SCOPED_TRACE(tileSize);
    TileEwaSplatter splatter(gl::ShaderLibrary(), tileSize);
    splatter.setFrame(frame);
    splatter.draw(size, size);
    const std::vector<glm::vec4> picture = splatter.picture();
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const double dx = x + 0.5 - 8.0, dy = y + 0.5 - 8.0;
        const double r = 0.01 * (dx * dx + dy * dy);
        // Both tails open: the whole kernel's depth, share 1.
        const double depth = count * double(amplitude) * windowedGaussian(r, cutoff);
        const double alpha = 1.0 - std::exp(-depth);
        const glm::vec4 p = picture[size_t(y * size + x)];
        ASSERT_NEAR(p.a, alpha, 2e-3 * alpha) << x << "," << y;
        ASSERT_NEAR(p.g, 0.5 * alpha, 2e-3 * alpha) << x << "," << y;
      }
    }
  }
}

// Over half a million faint splats over one tile in 24 slabs: more loop iterations than llvmpipe
// lets one invocation run (65535), so there the composite runs in chunks of slabs; every splat
// is added, checked against the closed form.
TEST_F(TileEwaSplatterTest, AddsEverySplatOfABusyTileThroughManySlabs) {
  const int slabs = 24, perSlab = 24000, size = 8;
  const float amplitude = 2e-6f, cutoff = 5.0f;
  TileEwaFrame frame;
  frame.cutoff = cutoff;
  frame.termination = 1.0f;
  TileEwaSplat splat;
  splat.box = glm::vec4(4.0f, 4.0f, 20.0f, 20.0f);
  splat.conic = glm::vec4(0.01f, 0.0f, 0.01f, amplitude);
  splat.color = glm::vec4(1.0f, 0.5f, 0.25f, 0.0f);
  for (int s = 0; s < slabs; ++s) {
    frame.slabDepths.emplace_back(10.0f + 2.0f * float(s), 12.0f + 2.0f * float(s));
    splat.depth = glm::vec4(11.0f + 2.0f * float(s), 0.0f, 0.0f, 0.5f);
    for (int n = 0; n < perSlab; ++n) {
      frame.entries.emplace_back(
          uint32_t(frame.splats.size()) | SlabPartition::kFirstSlab | SlabPartition::kLastSlab,
          uint32_t(s));
      frame.splats.push_back(splat);
    }
  }
  TileEwaSplatter splatter(gl::ShaderLibrary(), 8);
  splatter.setFrame(frame);
  splatter.draw(size, size);
  const std::vector<glm::vec4> picture = splatter.picture();
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double dx = x + 0.5 - 4.0, dy = y + 0.5 - 4.0;
      const double r = 0.01 * (dx * dx + dy * dy);
      // Both tails open in every slab: each slab its splats' whole depth.
      const double depth = slabs * perSlab * double(amplitude) * windowedGaussian(r, cutoff);
      const double alpha = 1.0 - std::exp(-depth);
      const glm::vec4 p = picture[size_t(y * size + x)];
      ASSERT_NEAR(p.a, alpha, 2e-3 * alpha) << x << "," << y;
      ASSERT_NEAR(p.g, 0.5 * alpha, 2e-3 * alpha) << x << "," << y;
    }
  }
}

}  // namespace
}  // namespace ewa::test
