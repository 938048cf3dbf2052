// Image tests: headless renders compared with reference PNGs in tests/reference.
#include <filesystem>

#include "app/options.h"
#include "app/scene.h"
#include "image_compare.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class ReferenceImages : public RenderFixture {
 protected:
  // Renders like `ewaview ARGS --output`, through the same scene and camera code.
  Image8 renderLikeCli(std::vector<const char*> args) {
    args.insert(args.begin(), "ewaview");
    Options o;
    const ParseResult pr = parseCommandLine(int(args.size()), args.data(), &o);
    EXPECT_TRUE(pr.run);
    scene_ = std::make_unique<Scene>(loadScene(o));
    renderer()->setVolume(scene_->volume);
    renderer()->setTransferFunction(scene_->transferFunction);
    renderer()->render(initialCamera(scene_->volume, o), o.render, o.width, o.height);
    return renderer()->readImage();
  }
  std::unique_ptr<Scene> scene_;
};

// Tolerances: llvmpipe is deterministic, but float summation order may differ between Mesa
// versions; a mean of 1/255 per channel and 1% of pixels off by more than 8 allows that and
// nothing more (a wrong footprint or compositing step moves whole regions).
constexpr double kMean = 1.0;
constexpr int kPixel = 8;
constexpr double kBad = 0.01;

TEST_F(ReferenceImages, Engine) {
  const std::string path = std::string(EWA_SHARED_DATA) + "/engine/engine.nhdr";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data absent: " << path;
  const Image8 img = renderLikeCli({path.c_str(), "--resolution", "160,160", "--camera-position",
                                    "400,-250,300", "--camera-view-up", "0,0,1"});
  EXPECT_TRUE(matchesReference("engine_ewa", img, kMean, kPixel, kBad));
}

TEST_F(ReferenceImages, SphereEachFilter) {
  for (const char* f : {"ewa", "swan", "plain"}) {
    const Image8 img = renderLikeCli({"--synthetic", "sphere:24", "--resolution", "96,96",
                                      "--filter", f, "--background", "0.1,0.1,0.2"});
    EXPECT_TRUE(matchesReference(std::string("sphere_") + f, img, kMean, kPixel, kBad));
  }
}

TEST_F(ReferenceImages, CheckerboardToTheHorizonEachFilter) {
  for (const char* f : {"ewa", "swan", "plain"}) {
    const Image8 img = renderLikeCli({"--synthetic", "checkerboard", "--resolution", "160,100",
                                      "--camera-position", "200,-120,25", "--camera-focal-point",
                                      "200,400,0", "--camera-view-up", "0,0,1", "--filter", f});
    EXPECT_TRUE(matchesReference(std::string("checkerboard_") + f, img, kMean, kPixel, kBad));
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
    EXPECT_TRUE(matchesReference(names[m], renderLikeCli(args), kMean, kPixel, kBad));
  }
}

TEST_F(ReferenceImages, SurfaceSplatsWithVolumeSplats) {
  // The sphere's iso-surface as surface splats, shaded, inside the semi-transparent ball.
  const Image8 img = renderLikeCli({"--synthetic", "sphere:24", "--resolution", "96,96",
                                    "--surface-threshold", "200", "--surface-opacity", "0.6",
                                    "--shading", "--background", "0.1,0.1,0.2"});
  EXPECT_TRUE(matchesReference("sphere_surface", img, kMean, kPixel, kBad));
}

}  // namespace
}  // namespace ewa::test
