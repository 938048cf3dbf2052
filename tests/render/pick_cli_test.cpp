// --pick as a user runs it: the pixels that show the volume in the headless picture are the
// ones whose pick hits it, the JSON it prints, and its usage errors.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "image_compare.h"
#include "io/png_io.h"

namespace ewa::test {
namespace {

// A ball off the centre of a wider-than-high picture, up and to the left: a pick that mirrored
// rows or columns, or took the wrong aspect, would hit where the picture shows background.
const std::string kScene =
    "--synthetic sphere:32 --resolution 80,60 --camera-focal-point 27,6,15.5 "
    "--camera-position 27,6,110";

nlohmann::ordered_json pick(int x, int y, const std::string& scene = kScene) {
  const CliRun r =
      runEwaview(scene + " --pick " + std::to_string(x) + "," + std::to_string(y), "pick");
  EXPECT_EQ(r.code, 0) << r.err;
  return nlohmann::ordered_json::parse(r.out, nullptr, false);
}

TEST(PickCli, PixelsThatShowTheBallAreTheOnesWhosePickHitsIt) {
  const std::string png = testOutputDir() + "/pick_scene.png";
  const CliRun r = runEwaview(kScene + " --output " + png, "pick");
  ASSERT_EQ(r.code, 0) << r.err;
  const Image8 image = readPng(png);
  ASSERT_EQ(image.width, 80);
  int shown = 0, empty = 0;
  for (int y = 2; y < 60; y += 7) {
    for (int x = 3; x < 80; x += 9) {
      const uint8_t* p = &image.pixels[size_t(y * image.width + x) * size_t(image.channels)];
      const int level = std::max({p[0], p[1], p[2]});
      if (level > 2 && level < 40) continue;  // the ball's soft rim: either may hold
      const nlohmann::ordered_json j = pick(x, y);
      ASSERT_TRUE(j.is_object());
      const bool hit = j["hit"].get<bool>();
      EXPECT_EQ(hit, level >= 40) << "pixel " << x << "," << y << " level " << level;
      (level >= 40 ? shown : empty)++;
      if (hit) {
        // The point lies in the ball (radius 12.8 about 15.5) and its value is visible.
        const double dx = j["world"][0].get<double>() - 15.5,
                     dy = j["world"][1].get<double>() - 15.5,
                     dz = j["world"][2].get<double>() - 15.5;
        EXPECT_LT(std::sqrt(dx * dx + dy * dy + dz * dz), 14.0) << j.dump();
        EXPECT_GT(j["value"].get<double>(), 0.0) << j.dump();
        EXPECT_GT(j["opacity"].get<double>(), 0.01) << j.dump();
      }
    }
  }
  // The ball covers the upper left, the background the rest: both were tried.
  EXPECT_GE(shown, 5);
  EXPECT_GE(empty, 5);
}

TEST(PickCli, JsonNamesThePointTheVoxelAndTheValue) {
  // The pixel on the view axis through the ball's centre. The ball is translucent and nearly
  // uniform: the point is where the light lost along the 25.6 units through it reaches half
  // its total, at depth -ln(1 - opacity / 2) / tau behind the front, tau = -ln(1 - opacity) / 25.6.
  const std::string centred =
      "--synthetic sphere:32 --resolution 1,1 --camera-focal-point 15.5,15.5,15.5 "
      "--camera-position 15.5,15.5,110";
  const nlohmann::ordered_json j = pick(0, 0, centred);
  ASSERT_TRUE(j["hit"].get<bool>()) << j.dump();
  const std::vector<std::string> keys = {"pixel", "hit",   "world",   "index",
                                         "voxel", "value", "opacity", "distance"};
  size_t n = 0;
  for (auto it = j.begin(); it != j.end(); ++it, ++n) EXPECT_EQ(it.key(), keys.at(n));
  const double opacity = j["opacity"].get<double>();
  ASSERT_GT(opacity, 0.3);
  ASSERT_LT(opacity, 0.95);
  const double tau = -std::log(1.0 - opacity) / 25.6;
  const double depth = -std::log(1.0 - 0.5 * opacity) / tau;
  EXPECT_NEAR(j["world"][2].get<double>(), 15.5 + 12.8 - depth, 0.5) << j.dump();
  EXPECT_NEAR(j["world"][0].get<double>(), 15.5, 1e-9);
  const auto voxel = j["voxel"].get<std::vector<int>>();
  EXPECT_EQ(voxel[2], int(std::lround(j["index"][2].get<double>())));
  EXPECT_NEAR(j["distance"].get<double>(), 110.0 - j["world"][2].get<double>(), 1e-6);
  // MIP picks the brightest point instead: inside the ball, at its value 255.
  const nlohmann::ordered_json mip = pick(0, 0, centred + " --render-mode mip");
  ASSERT_TRUE(mip["hit"].get<bool>()) << mip.dump();
  EXPECT_NEAR(mip["value"].get<double>(), 255.0, 0.5);
}

TEST(PickCli, UsageErrorsAreOneLineAndExitTwo) {
  for (const char* bad : {"--pick 80,10", "--pick 10,-1", "--pick 10", "--pick a,b",
                          "--pick 5,5 --info", "--pick 5,5 --output x.png"}) {
    const CliRun r = runEwaview(kScene + " " + bad, "pick");
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_EQ(lineCount(r.err), 1) << bad << ": " << r.err;
    EXPECT_NE(r.err.find("--pick"), std::string::npos) << bad << ": " << r.err;
  }
}

}  // namespace
}  // namespace ewa::test
