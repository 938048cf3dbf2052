// Turntables from the command line: frame names (pattern or folder), frame cameras, errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_run.h"
#include "image_compare.h"
#include "io/png_io.h"

namespace ewa::test {
namespace {

namespace fs = std::filesystem;

CliRun ewaview(const std::string& args) {
  return runEwaview(args, "turntable");
}

// A fresh folder for one test's frames.
std::string freshDir(const std::string& name) {
  const fs::path dir = fs::path(testOutputDir()) / name;
  fs::remove_all(dir);
  return dir.string();
}

double meanDifference(const Image8& a, const Image8& b) {
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  double sum = 0.0;
  for (size_t n = 0; n < std::min(a.pixels.size(), b.pixels.size()); ++n)
    sum += std::abs(int(a.pixels[n]) - int(b.pixels[n]));
  return sum / double(std::max<size_t>(1, a.pixels.size()));
}

// Marschner-Lobb (24^3, voxel centres 0..23) from +z: orbiting about +y by 90 degrees puts
// the eye on +x, where the function looks different (it varies along z, not along x).
const std::string kScene =
    "--synthetic marschner-lobb:24 --resolution 48,40 --camera-focal-point 11.5,11.5,11.5 "
    "--camera-view-up 0,1,0 ";

TEST(Turntable, PatternFramesMatchSinglePicturesFromTheOrbitedCameras) {
  const std::string dir = freshDir("turntable_pattern");
  CliRun r = ewaview(kScene + "--camera-position 11.5,11.5,71.5 --turntable 4 --output " + dir +
                     "/tt_%02d.png");
  ASSERT_EQ(r.code, 0) << r.err;
  for (int f = 0; f < 4; ++f)
    EXPECT_TRUE(fs::exists(dir + "/tt_0" + std::to_string(f) + ".png")) << f;
  EXPECT_FALSE(fs::exists(dir + "/tt_04.png"));
  for (const auto& e : fs::directory_iterator(dir))  // atomic writes leave no temporaries
    EXPECT_EQ(e.path().extension(), ".png") << e.path();

  ASSERT_EQ(
      ewaview(kScene + "--camera-position 11.5,11.5,71.5 --output " + dir + "/front.png").code, 0);
  ASSERT_EQ(ewaview(kScene + "--camera-position 71.5,11.5,11.5 --output " + dir + "/side.png").code,
            0);
  const Image8 f0 = readPng(dir + "/tt_00.png"), f1 = readPng(dir + "/tt_01.png");
  const Image8 front = readPng(dir + "/front.png"), side = readPng(dir + "/side.png");
  EXPECT_EQ(f0.width, 48);
  EXPECT_EQ(f0.height, 40);
  EXPECT_LT(meanDifference(f0, front), 0.05);
  EXPECT_LT(meanDifference(f1, side), 0.5);
  // The frames do differ: the test would pass for a turntable that never turned otherwise.
  EXPECT_GT(meanDifference(f0, f1), 10.0 * std::max(0.05, meanDifference(f1, side)));
}

TEST(Turntable, FolderOutputNamesFramesInOrder) {
  const std::string dir = freshDir("turntable_folder") + "/frames";
  const CliRun r =
      ewaview("--synthetic sphere:12 --resolution 24,24 --turntable 3 --output " + dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;  // no progress noise when stderr is not a terminal
  int count = 0;
  for (const auto& e : fs::directory_iterator(dir)) count += e.is_regular_file();
  EXPECT_EQ(count, 3);
  for (const char* name : {"frame_000.png", "frame_001.png", "frame_002.png"})
    EXPECT_EQ(readPng(dir + "/" + name).width, 24) << name;
}

TEST(Turntable, BadUseIsOneLineAndNonZero) {
  const std::string dir = freshDir("turntable_bad");
  CliRun r = ewaview("--synthetic sphere:8 --turntable 3");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--turntable needs --output"), std::string::npos) << r.err;
  r = ewaview("--synthetic sphere:8 --turntable 3 --output " + dir + "/t_%s.png");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("t_%s.png: "), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(ewaview("--synthetic sphere:8 --turntable 0 --output " + dir).code, 2);
}

}  // namespace
}  // namespace ewa::test
