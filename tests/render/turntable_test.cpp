// Turntables from the command line: frame names (pattern or folder), frame cameras, the chosen
// renderer, videos, errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli_run.h"
#include "image_compare.h"
#include "io/png_io.h"
#include "io/video_reader.h"

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

// Mean absolute channel difference over RGB, for images with 3 or 4 channels of the same size.
double meanRgbDifference(const Image8& a, const Image8& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  if (a.width != b.width || a.height != b.height) return 1e9;
  double sum = 0.0;
  const size_t pixels = size_t(a.width) * a.height;
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c)
      sum += std::abs(int(a.pixels[p * a.channels + c]) - int(b.pixels[p * b.channels + c]));
  return sum / double(3 * std::max<size_t>(1, pixels));
}

TEST(Turntable, FramesComeFromTheRendererTheOptionsName) {
  const std::string dir = freshDir("turntable_renderer");
  fs::create_directories(dir);
  const std::string front = kScene + "--camera-position 11.5,11.5,71.5 ";
  ASSERT_EQ(
      ewaview(front + "--renderer shearwarp --turntable 2 --output " + dir + "/sw_%d.png").code, 0);
  ASSERT_EQ(ewaview(front + "--renderer shearwarp --output " + dir + "/sw.png").code, 0);
  ASSERT_EQ(ewaview(front + "--output " + dir + "/splat.png").code, 0);
  const Image8 frame = readPng(dir + "/sw_0.png"), single = readPng(dir + "/sw.png");
  EXPECT_EQ(frame.pixels, single.pixels);  // same renderer, same camera: the same picture
  // The two renderers' pictures differ by far more than nothing, so a turntable drawn with the
  // splat renderer could not pass the line above.
  EXPECT_GT(meanDifference(single, readPng(dir + "/splat.png")), 1.0);
}

// Marschner-Lobb at a video-like size: frame 0 of each codec against the single picture.
// Tolerance: the codecs run at near-transparent quality (x264 crf 16, VP9 crf 20) and 4:2:0
// halves the colour resolution: a mean of 2.5 levels in 255 per channel over the frame (measured
// 1.4 for H.264 and 0.8 for VP9 after the RGB <-> YUV conversions were made exact).
TEST(Turntable, VideosHoldTheFramesAtTheirSizeAndRate) {
  const std::string dir = freshDir("turntable_video");
  fs::create_directories(dir);
  const std::string scene =
      "--synthetic marschner-lobb:24 --resolution 96,80 --camera-focal-point 11.5,11.5,11.5 "
      "--camera-view-up 0,1,0 --camera-position 11.5,11.5,71.5 ";
  ASSERT_EQ(ewaview(scene + "--output " + dir + "/single.png").code, 0);
  const Image8 single = readPng(dir + "/single.png");
  for (const auto& [name, codec] :
       {std::pair<std::string, std::string>{"spin.mp4", "h264"}, {"spin.webm", "vp9"}}) {
    const CliRun r = ewaview(scene + "--turntable 8 --fps 12 --output " + dir + "/" + name);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;  // no encoder chatter
    const DecodedVideo video = readVideo(dir + "/" + name);
    EXPECT_EQ(video.codec, codec);
    EXPECT_DOUBLE_EQ(video.fps, 12.0) << name;
    ASSERT_EQ(video.frames.size(), 8u) << name;
    EXPECT_EQ(video.frames[0].width, 96);
    EXPECT_EQ(video.frames[0].height, 80);
    const double loss = meanRgbDifference(video.frames[0], single);
    EXPECT_LT(loss, 2.5) << name;
    // The video turns: frame 2 (90 degrees on) is far from frame 0.
    EXPECT_GT(meanRgbDifference(video.frames[2], single), 5.0 * std::max(loss, 0.5)) << name;
    std::cout << name << ": frame 0 differs from the PNG by " << loss << " levels on average\n";
  }
  for (const auto& e : fs::directory_iterator(dir))  // temporaries were renamed into place
    EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
}

TEST(Turntable, OddSizedVideosDropTheLastRowAndColumn) {
  const std::string dir = freshDir("turntable_odd");
  ASSERT_EQ(
      ewaview("--synthetic sphere:12 --resolution 33,21 --turntable 2 --output " + dir + "/odd.mp4")
          .code,
      0);
  const DecodedVideo video = readVideo(dir + "/odd.mp4");
  ASSERT_EQ(video.frames.size(), 2u);
  EXPECT_EQ(video.frames[0].width, 32);
  EXPECT_EQ(video.frames[0].height, 20);
}

TEST(Turntable, BadVideoPathsAreOneLineAndExitOne) {
  const std::string dir = freshDir("turntable_bad_video");
  fs::create_directories(dir + "/taken.mp4");
  std::ofstream(dir + "/file") << "x";
  for (const std::string& out : {dir + "/taken.mp4", dir + "/file/spin.mp4", dir + "/spin.avi",
                                 std::string("/proc/x.webm")}) {
    const CliRun r = ewaview("--synthetic sphere:8 --turntable 2 --output " + out);
    EXPECT_EQ(r.code, 1) << out;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("ewaview: " + out + ": ", 0), 0u) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir + "/spin.avi"));
  EXPECT_EQ(ewaview("--synthetic sphere:8 --turntable 2 --fps 0 --output " + dir + "/a.mp4").code,
            2);
}

}  // namespace
}  // namespace ewa::test
