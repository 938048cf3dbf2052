// --crop and --clip-plane as a user gives them: usage errors, and pictures from both renderers.
#include <gtest/gtest.h>

#include <string>

#include "ci_skip.h"
#include "cli_run.h"
#include "image_compare.h"
#include "io/png_io.h"

namespace ewa::test {
namespace {

CliRun ewaview(const std::string& args) {
  return runEwaview(args, "clip_cli");
}

TEST(ClipCli, HelpListsTheOptions) {
  const CliRun r = ewaview("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--crop"), std::string::npos);
  EXPECT_NE(r.out.find("--clip-plane"), std::string::npos);
}

TEST(ClipCli, MalformedValuesAreOneLineUsageErrors) {
  const std::string base = "--synthetic sphere:8 --output " + testOutputDir() + "/clip_bad.png ";
  const struct {
    const char* args;
    const char* message;
  } cases[] = {
      {"--crop 0,1,0,1,0", "expected 6 comma-separated numbers, got 5"},
      {"--crop 0,1,0,1,0,zz", "'zz' is not a finite number"},
      {"--crop 0,1,3,2,0,1", "Y0 must be less than Y1"},
      {"--crop=0,1,0,1,0,nan", "not a finite number"},
      {"--clip-plane 1,2,3,0,0,0", "the normal is zero"},
      {"--clip-plane 1,2,3,4", "expected 6"},
      {"--clip-plane 0,0,0,1,0,0 --clip-plane 0,0,0,1,0,0 --clip-plane 0,0,0,1,0,0 "
       "--clip-plane 0,0,0,1,0,0 --clip-plane 0,0,0,1,0,0 --clip-plane 0,0,0,1,0,0 "
       "--clip-plane 0,0,0,1,0,0",
       "at most 6 planes"},
  };
  for (const auto& c : cases) {
    const CliRun r = ewaview(base + c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(lineCount(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
  }
}

// Both renderers: the box keeps the left half of the ball (x <= 16), a plane with a leading
// minus in its normal keeps the same half, and nothing is drawn right of the cut.
TEST(ClipCli, CropAndPlaneCutThePictureForBothRenderers) {
  const std::string dir = testOutputDir();
  for (const std::string renderer : {"splat", "shearwarp"}) {
    const std::string base =
        "--synthetic sphere:32 --resolution 64,64 --camera-orthographic "
        "--renderer " +
        renderer + " --output " + dir + "/clip_" + renderer;
    CliRun r = ewaview(base + "_full.png");
    if (r.code != 0) {
      EWA_SKIP_UNLESS_CI() << r.err;
    }
    ASSERT_EQ(r.code, 0) << r.err;
    r = ewaview(base + "_crop.png --crop -10,16,-10,50,-10,50");
    ASSERT_EQ(r.code, 0) << r.err;
    r = ewaview(base + "_plane.png --clip-plane=16,0,0,-1,0,0");
    ASSERT_EQ(r.code, 0) << r.err;
    const Image8 full = readPng(dir + "/clip_" + renderer + "_full.png");
    const Image8 crop = readPng(dir + "/clip_" + renderer + "_crop.png");
    const Image8 plane = readPng(dir + "/clip_" + renderer + "_plane.png");
    long fullRight = 0, cropRight = 0, cropLeft = 0, differ = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x)
        for (int c = 0; c < 3; ++c) {
          const size_t p = (size_t(y) * 64 + x) * 4 + c;  // readPng gives RGBA
          (x < 28 ? cropLeft : cropRight) += x < 28 || x > 36 ? crop.pixels[p] : 0;
          if (x > 36) fullRight += full.pixels[p];
          differ += std::abs(int(crop.pixels[p]) - int(plane.pixels[p])) > 2;
        }
    EXPECT_GT(fullRight, 1000) << renderer;
    EXPECT_EQ(cropRight, 0) << renderer;
    EXPECT_GT(cropLeft, 1000) << renderer;
    EXPECT_LT(differ, 64) << renderer << ": box and plane cut differently";
  }
}

}  // namespace
}  // namespace ewa::test
