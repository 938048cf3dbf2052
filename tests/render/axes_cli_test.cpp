// --axis as a user runs it: the headless picture, a turntable's frames and nothing else gain
// the orientation axes, exactly the strokes core/orientation_axes paints, in the corner only.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "cli_run.h"
#include "core/camera.h"
#include "core/orientation_axes.h"
#include "image_compare.h"
#include "io/png_io.h"

namespace ewa::test {
namespace {

const std::string kScene =
    "--synthetic sphere:32 --resolution 96,80 --camera-position 70,-40,50 "
    "--camera-focal-point 15.5,15.5,15.5 --camera-view-up 0,0,1";

// The picture, and the levels two runs of it may differ by (runToRunLevels: 0 on llvmpipe).
Image8 rendered(const std::string& extra, const std::string& name, int* levels = nullptr) {
  const std::string png = testOutputDir() + "/" + name + ".png";
  const CliRun r = runEwaview(kScene + " " + extra + " --stats --output " + png, "axes");
  EXPECT_EQ(r.code, 0) << r.err;
  if (levels && r.code == 0) *levels = runToRunLevels(r.out);
  return readPng(png);
}

TEST(AxesCli, TheAxisPictureIsThePlainOneWithTheAxesPaintedInTheCorner) {
  int levels = 0;
  const Image8 plain = rendered("", "axes_plain", &levels);
  const Image8 axes = rendered("--axis", "axes_on");
  ASSERT_EQ(plain.width, 96);
  ASSERT_EQ(axes.pixels.size(), plain.pixels.size());
  Camera camera;
  camera.position = {70, -40, 50};
  camera.focalPoint = glm::dvec3(15.5);
  camera.viewUp = {0, 0, 1};
  Image8 expected = plain;
  drawStrokes(expected, orientationAxes(camera.rotation(), false, axesPlacement(96, 80)));
  EXPECT_LE(maxDifference(axes, expected), levels);
  // The strokes changed pixels, all of them in the bottom-right corner, in the three colours.
  int changed = 0, reddish = 0, greenish = 0, bluish = 0;
  for (int y = 0; y < 80; ++y) {
    for (int x = 0; x < 96; ++x) {
      const size_t i = size_t(y * 96 + x) * size_t(axes.channels);
      const uint8_t* a = &axes.pixels[i];
      const uint8_t* p = &plain.pixels[i];
      if (std::equal(a, a + 3, p, [&](uint8_t u, uint8_t v) { return std::abs(u - v) <= levels; }))
        continue;
      ++changed;
      EXPECT_GE(x, 96 / 3) << y;  // the picture's lower right
      EXPECT_GE(y, 80 / 4) << x;
      reddish += a[0] > 150 && a[1] < 110 && a[2] < 110;
      greenish += a[1] > 150 && a[0] < 130 && a[2] < 130;
      bluish += a[2] > 180 && a[0] < 130;
    }
  }
  EXPECT_GT(changed, 60);
  EXPECT_GT(reddish, 3);
  EXPECT_GT(greenish, 3);
  EXPECT_GT(bluish, 3);
}

TEST(AxesCli, TurntableFramesCarryTheAxesToo) {
  int levels = 0;
  const Image8 axes = rendered("--axis", "axes_single", &levels);
  const std::string dir = testOutputDir() + "/axes_turntable";
  std::filesystem::remove_all(dir);
  const CliRun r = runEwaview(kScene + " --axis --turntable 2 --output " + dir + "/", "axes");
  ASSERT_EQ(r.code, 0) << r.err;
  // Frame 0 is the start camera's picture.
  EXPECT_LE(maxDifference(readPng(dir + "/frame_000.png"), axes), levels);
}

}  // namespace
}  // namespace ewa::test
