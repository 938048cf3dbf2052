// Image tests: headless renders compared with reference PNGs in tests/reference.
#include <cstdio>
#include <filesystem>
#include <vector>

#include "app/options.h"
#include "app/scene.h"
#include "image_compare.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class ReferenceImages : public RenderFixture {
 protected:
  // Renders like `ewaview ARGS --output`, through the same scene and camera code.
  // The references are the rasterized pictures (a GPU's path); where the options leave the
  // splatter to auto, the rasterizer draws (`splatter` otherwise).
  Image8 renderLikeCli(std::vector<const char*> args, Splatter splatter = Splatter::Raster) {
    args.insert(args.begin(), "ewaview");
    Options o;
    const ParseResult pr = parseCommandLine(int(args.size()), args.data(), &o);
    EXPECT_TRUE(pr.run);
    if (o.render.splatter == Splatter::Auto) o.render.splatter = splatter;
    scene_ = std::make_unique<Scene>(loadScene(o));
    renderer()->setVolume(scene_->volume);
    renderer()->setTransferFunction(scene_->transferFunction);
    renderer()->render(initialCamera(scene_->volume, o), o.render, o.width, o.height);
    return renderer()->readImage();
  }
  std::unique_ptr<Scene> scene_;
};

// Tolerances, over RGB and the pixels the object covers (image_compare.h): llvmpipe is
// deterministic, but float summation order may differ between Mesa versions; a mean of 1/255
// per channel and 1% of covered pixels off by more than 8 allows that and nothing more (a wrong
// footprint or compositing step moves whole regions).
constexpr double kMean = 1.0;
constexpr int kPixel = 8;
constexpr double kBad = 0.01;
const Rgb8 kBlack = backgroundRgb8(0, 0, 0);
const Rgb8 kBlue = backgroundRgb8(0.1, 0.1, 0.2);

TEST_F(ReferenceImages, Engine) {
  const std::string path = std::string(EWA_SHARED_DATA) + "/engine/engine.nhdr";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data absent: " << path;
  const Image8 img = renderLikeCli({path.c_str(), "--resolution", "160,160", "--camera-position",
                                    "400,-250,300", "--camera-view-up", "0,0,1"});
  EXPECT_TRUE(matchesReference("engine_ewa", img, kBlack, kMean, kPixel, kBad));
  // The CPU splatter's (auto's on a software rasterizer): its slabs at the picture's pixels in
  // floats part from the rasterizer's coarser half-float ones by about a level more.
  const Image8 cpu = renderLikeCli({path.c_str(), "--resolution", "160,160", "--camera-position",
                                    "400,-250,300", "--camera-view-up", "0,0,1"},
                                   Splatter::Cpu);
  EXPECT_TRUE(renderer()->stats().cpu);
  EXPECT_TRUE(matchesReference("engine_ewa", cpu, kBlack, 2.0 * kMean, kPixel, kBad));
}

// A magnified ball: the three filters draw it alike (their references differed by at most 2
// levels, swan's and plain's were identical), so only EWA's is kept.
TEST_F(ReferenceImages, Sphere) {
  const Image8 img = renderLikeCli(
      {"--synthetic", "sphere:24", "--resolution", "96,96", "--background", "0.1,0.1,0.2"});
  EXPECT_TRUE(matchesReference("sphere_ewa", img, kBlue, kMean, kPixel, kBad));
}

// Scenes where the filters differ: minified sheets receding to the horizon. Each filter's
// picture must match its own reference and lie far from the other filters' references, so a
// mix-up of filters (or a filter that stops doing anything) fails.
struct FilterScene {
  const char* name;
  std::vector<const char*> args;
};

const std::vector<FilterScene>& filterScenes() {
  static const std::vector<FilterScene> scenes = {
      // Swan's Fig. 7, the README's view.
      {"checkerboard",
       {"--synthetic", "checkerboard", "--resolution", "160,100", "--camera-position",
        "200,-120,25", "--camera-focal-point", "200,400,0", "--camera-view-up", "0,0,1"}},
      // Finer squares seen from higher: minified everywhere beyond the first rows.
      {"checkerboard4",
       {"--synthetic", "checkerboard:4", "--resolution", "120,90", "--camera-position",
        "200,-60,60", "--camera-focal-point", "200,300,0", "--camera-view-up", "0,0,1"}},
      // Zwicker's Fig. 8: 4:1 kernels, where Swan's isotropic stretch blurs.
      {"zebra4",
       {"--synthetic", "zebra:4", "--resolution", "160,100", "--camera-position", "128,-40,12",
        "--camera-focal-point", "128,256,0", "--camera-view-up", "0,0,1"}}};
  return scenes;
}

TEST_F(ReferenceImages, EachFilterIsClosestToItsOwnReference) {
  const char* filters[] = {"ewa", "swan", "plain"};
  for (const FilterScene& scene : filterScenes()) {
    for (const char* f : filters) {
      std::vector<const char*> args = scene.args;
      // Pre-classified, as the papers compare the filters (at the default kernel width).
      args.insert(args.end(), {"--filter", f, "--classification", "pre"});
      const Image8 img = renderLikeCli(args);
      const std::string own = std::string(scene.name) + "_" + f;
      EXPECT_TRUE(matchesReference(own, img, kBlack, kMean, kPixel, kBad));
      for (const char* g : filters) {
        if (g == f) continue;
        const std::string other = std::string(scene.name) + "_" + g;
        Image8 ref;
        try {
          ref = readReference(other);
        } catch (const std::exception& e) {
          ADD_FAILURE() << e.what();
          continue;
        }
        const ImageDifference d = compareCovered(img, ref, kBlack, kPixel);
        std::printf("%s: %s picture against %s reference: mean %.2f, %.1f%% off by > %d\n",
                    scene.name, f, g, d.mean, d.badFraction * 100, kPixel);
        // Far outside the tolerance for its own reference (measured: means 16 to 40).
        EXPECT_GT(d.mean, 8.0 * kMean) << own << " against " << other;
        EXPECT_GT(d.badFraction, 10.0 * kBad) << own << " against " << other;
      }
    }
  }
}

TEST_F(ReferenceImages, RenderModes) {
  const std::vector<std::vector<const char*>> modes = {
      {"--render-mode", "xray", "--xray-scale", "0.04"},
      {"--render-mode", "xray", "--xray-map", "sum", "--xray-scale", "0.015"},
      {"--render-mode", "mip"},
      {"--render-mode", "composite", "--shading", "--compositing", "back-to-front"},
  };
  const char* names[] = {"modes_xray_exp", "modes_xray_sum", "modes_mip", "modes_shaded"};
  for (size_t m = 0; m < modes.size(); ++m) {
    std::vector<const char*> args = {"--synthetic", "marschner-lobb:32", "--resolution",
                                     "80,80",       "--camera-position", "60,-40,70"};
    args.insert(args.end(), modes[m].begin(), modes[m].end());
    EXPECT_TRUE(matchesReference(names[m], renderLikeCli(args), kBlack, kMean, kPixel, kBad));
  }
}

TEST_F(ReferenceImages, SurfaceSplatsWithVolumeSplats) {
  // The sphere's iso-surface as surface splats, shaded, inside the semi-transparent ball.
  const Image8 img = renderLikeCli({"--synthetic", "sphere:24", "--resolution", "96,96",
                                    "--surface-threshold", "200", "--surface-opacity", "0.6",
                                    "--shading", "--background", "0.1,0.1,0.2"});
  EXPECT_TRUE(matchesReference("sphere_surface", img, kBlue, kMean, kPixel, kBad));
}

}  // namespace
}  // namespace ewa::test
