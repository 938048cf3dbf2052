// A brick read alone with its ghost voxels (and the whole volume's value range, histogram, data
// box and slab grid anchor) draws the same picture, to the bit, as the whole volume cut to that
// brick: post- and pre-classified, default and oblique views, perspective and orthographic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/scene.h"
#include "core/synthetic_volume.h"
#include "core/volume_downsample.h"
#include "dist/mpi_brick_source.h"
#include "dist/mpi_render.h"
#include "dist/mpi_window.h"

namespace ewa::dist {
namespace {

Options parse(const std::string& args) {
  std::vector<std::string> words{"ewaview"};
  size_t at = 0;
  while (at < args.size()) {
    const size_t end = std::min(args.find(' ', at), args.size());
    if (end > at) words.push_back(args.substr(at, end - at));
    at = end + 1;
  }
  std::vector<const char*> argv;
  for (const std::string& w : words) argv.push_back(w.c_str());
  Options o;
  const ParseResult r = parseCommandLine(int(argv.size()), argv.data(), &o);
  EXPECT_TRUE(r.run) << args;
  return o;
}

// Every brick of a `ranks`-way split drawn from its ghosted read equals the whole volume's
// picture cut to it, channel by channel after the final pass (8 bits) and in float.
void expectBricksDrawTheWholeCut(const std::string& args, int ranks) {
  SCOPED_TRACE(args);
  const Options o = parse(args + " --termination 1 --output unused.png");
  std::unique_ptr<BrickSource> source = BrickSource::open(o);
  const WholeGrid& grid = source->grid();
  const SyntheticVolume whole = makeSyntheticVolume(o.synthetic);
  const TransferFunction tf = *whole.transferFunction;
  const Camera camera = initialCamera(whole.volume, o);
  const int w = o.width, h = o.height;
  const std::array<int64_t, 3> ghost =
      ghostVoxels(frameGhostReach(grid, camera, o.render, w, h), grid.spacing);
  const BrickSplit split = splitBricks(VoxelWeights(grid.dims), ranks);
  for (const VoxelBox& brick : split.bricks) {
    VoxelRegion region;
    VoxelBox local;
    DataBox box = whole.volume.indexDataBox();
    for (size_t a = 0; a < 3; ++a) {
      region.lo[a] = std::max<int64_t>(brick.low[a] - ghost[a], 0);
      region.hi[a] = std::min<int64_t>(brick.high[a] + ghost[a], grid.dims[a]);
      local.low[a] = brick.low[a] - region.lo[a];
      local.high[a] = brick.high[a] - region.lo[a];
      box.low[int(a)] -= double(region.lo[a]);
      box.high[int(a)] -= double(region.lo[a]);
    }
    Volume part = source->read(region);
    part.setValueStatistics(whole.volume.minValue(), whole.volume.maxValue(),
                            whole.volume.histogram());
    part.setIndexDataBox(box);
    // The same grid for both: the nearest kernel of the brick's own voxels, found from the
    // brick read alone as ewaview-mpi finds it.
    const ClassifiedSplats splats = classifySplats(part, tf, splatClassification(o.render));
    const double anchor = brickKernelFront(part, local, splats, camera, o.render, w, h);
    ASSERT_TRUE(std::isfinite(anchor));
    const std::vector<float> cut = renderBrick(whole.volume, brick, tf, camera, o.render, w, h,
                                               anchor, o.backend, o.shaderDir);
    const std::vector<float> alone =
        renderBrick(part, local, tf, camera, o.render, w, h, anchor, o.backend, o.shaderDir);
    ASSERT_EQ(cut.size(), alone.size());
    float worst = 0.0f, sum = 0.0f;
    for (size_t i = 0; i < cut.size(); ++i) {
      worst = std::max(worst, std::abs(cut[i] - alone[i]));
      sum += cut[i];
    }
    EXPECT_GT(sum, 0.0f) << "an empty brick picture";
    const Image8 a = finishPicture(cut, w, h, o.render), b = finishPicture(alone, w, h, o.render);
    int levels = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
      levels = std::max(levels, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
    EXPECT_EQ(levels, 0) << "brick " << brick.low[0] << "," << brick.low[1] << "," << brick.low[2]
                         << ": float difference up to " << worst;
  }
}

const std::string kVolume = "--synthetic marschner-lobb:41 --resolution 96,96";

TEST(BrickPicture, PostClassifiedDefaultView) {
  expectBricksDrawTheWholeCut(kVolume, 3);
}

TEST(BrickPicture, ObliquePreClassifiedPerspectiveAndOrthographic) {
  const std::string oblique = kVolume + " --camera-position 75,-40,95 --classification pre";
  expectBricksDrawTheWholeCut(oblique, 3);
  expectBricksDrawTheWholeCut(oblique + " --camera-orthographic", 2);
}

TEST(BrickPicture, ObliquePostClassifiedClose) {
  expectBricksDrawTheWholeCut(kVolume + " --camera-position 45,-20,55", 2);
}

// The window's stand-in for the whole volume: the whole itself where it fits, else averaged
// down by a power of 2 a slab of z-layers at a time, as downsampleVolume does the whole; either
// way with the statistics it is given and the whole's direction.
TEST(StandInVolume, TheWholeOrItsAverageWithTheGivenStatistics) {
  const Options o = parse(kVolume);
  std::unique_ptr<BrickSource> source = BrickSource::open(o);
  const Volume whole = makeSyntheticVolume(o.synthetic).volume;
  Volume statistics = whole;
  std::vector<uint64_t> histogram(size_t(Volume::histogramBins()), 7);
  statistics.setValueStatistics(-1.0, 2.0, histogram);

  const Volume same = standInVolume(*source, statistics, whole.voxelCount());
  EXPECT_EQ(same.dims(), whole.dims());
  EXPECT_EQ(same.bytes(), whole.bytes());
  EXPECT_EQ(same.minValue(), -1.0);
  EXPECT_EQ(same.maxValue(), 2.0);
  EXPECT_EQ(same.histogram(), histogram);

  const Volume coarse = standInVolume(*source, statistics, whole.voxelCount() / 8);
  const Volume expected = downsampleVolume(whole, 2);
  ASSERT_EQ(coarse.dims(), expected.dims());
  EXPECT_EQ(coarse.spacing(), expected.spacing());
  EXPECT_EQ(coarse.origin(), expected.origin());
  EXPECT_EQ(coarse.bytes(), expected.bytes());
  EXPECT_EQ(coarse.worldBoundsMin(), expected.worldBoundsMin());
  EXPECT_EQ(coarse.histogram(), histogram);
}

}  // namespace
}  // namespace ewa::dist
