// --tour: frames through camera bookmarks; the stops' frames are the bookmarks' own pictures
// (with their crop boxes), the frames between them other views; errors are one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli_run.h"
#include "core/view_options_text.h"
#include "image_compare.h"
#include "io/camera_bookmarks.h"
#include "io/png_io.h"

namespace ewa::test {
namespace {

namespace fs = std::filesystem;

Camera cameraAt(glm::dvec3 position, glm::dvec3 up) {
  Camera c;
  c.position = position;
  c.focalPoint = {15.5, 15.5, 15.5};  // sphere:32's centre
  c.viewUp = up;
  return c;
}

TEST(TourCli, StopsAreTheBookmarksPicturesAndTheLegsOtherViews) {
  const fs::path dir = fs::path(testOutputDir()) / "tour";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<CameraBookmark> marks(3);
  marks[0] = {"front", cameraAt({15.5, 15.5, 90.0}, {0, 1, 0}), {}};
  marks[1] = {"side", cameraAt({80.0, 15.5, 15.5}, {0, 1, 0}), {}};
  marks[1].clip.cropEnabled = true;  // half the ball cut away
  marks[1].clip.cropMin = {0, 0, 0};
  marks[1].clip.cropMax = {31, 31, 15};
  marks[2] = {"above", cameraAt({15.5, 70.0, 40.0}, {0, 0, -1}), {}};
  const std::string bookmarks = (dir / "ball.bookmarks.json").string();
  saveBookmarks(bookmarks, marks);

  const std::string common = "--synthetic sphere:32 --resolution 48,40 ";
  CliRun r = runEwaview(
      common + "--tour 5 --bookmarks " + bookmarks + " -o " + (dir / "t_%d.png").string(), "tour");
  ASSERT_EQ(r.code, 0) << r.err;
  Image8 frames[5];
  for (int f = 0; f < 5; ++f)
    frames[f] = readPng((dir / ("t_" + std::to_string(f) + ".png")).string());
  // Frames 0, 2 and 4 are the stops: the picture of each bookmark's view on its own.
  for (int stop = 0; stop < 3; ++stop) {
    SCOPED_TRACE(marks[size_t(stop)].name);
    const std::string png = (dir / ("stop_" + std::to_string(stop) + ".png")).string();
    r = runEwaview(
        common + viewOptionsText(marks[size_t(stop)].camera, {48, 40}, marks[size_t(stop)].clip) +
            " -o " + png,
        "tour");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_LE(maxDifference(frames[2 * stop], readPng(png)), 1);
  }
  // The cut-away half shows: the side stop differs from the same view uncropped.
  EXPECT_GT(maxDifference(frames[0], frames[2]), 40);
  EXPECT_GT(maxDifference(frames[1], frames[0]), 40);  // between the stops: another view
  EXPECT_GT(maxDifference(frames[1], frames[2]), 40);
}

// A volume in a read-only folder has its window bookmarks under the settings folder: --tour
// finds them there when none lie beside it.
TEST(TourCli, FindsTheWindowsBookmarksUnderTheSettingsFolder) {
  const fs::path dir = fs::path(testOutputDir()) / "tour_config";
  fs::remove_all(dir);
  fs::create_directories(dir / "data");
  const std::string volume = (dir / "data" / "cube.nrrd").string();
  std::ofstream(volume, std::ios::binary) << "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 8 8 8\n"
                                             "encoding: raw\n\n"
                                          << std::string(512, char(200));
  const std::string config = (dir / "config").string();
  const std::string out = " --resolution 24,24 -o " + (dir / "f_%d.png").string();
  CliRun r = runEwaview(volume + " --tour 3 --config-dir " + config + out, "tour");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(
      r.err.find("cube.bookmarks.json: no such bookmarks file (nor " + config + "/bookmarks/cube."),
      std::string::npos)
      << r.err;
  saveBookmarks(fallbackBookmarksPath(volume, config),
                {{"a", cameraAt({3.5, 3.5, 40}, {0, 1, 0}), {}},
                 {"b", cameraAt({40, 3.5, 3.5}, {0, 1, 0}), {}}},
                true);
  r = runEwaview(volume + " --tour 3 --config-dir " + config + out, "tour");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "f_2.png"));
}

TEST(TourCli, BadBookmarksAndOptionsAreOneLine) {
  const fs::path dir = fs::path(testOutputDir()) / "tour_bad";
  fs::create_directories(dir);
  const std::string one = (dir / "one.bookmarks.json").string();
  saveBookmarks(one, {{"only", cameraAt({0, 0, 90}, {0, 1, 0}), {}}});
  const std::string out = " -o " + (dir / "f_%d.png").string();
  CliRun r = runEwaview("--synthetic sphere:16 --tour 4 --bookmarks " + one + out, "tour");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(one + ": a tour needs two bookmarks or more (it holds 1)"),
            std::string::npos)
      << r.err;
  // A synthetic volume's bookmarks are only where the window keeps them: the settings folder.
  const std::string config = (dir / "config").string();
  r = runEwaview("--synthetic sphere:16 --tour 4 --config-dir " + config + out, "tour");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(config + "/bookmarks/synthetic-sphere:16."), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no such bookmarks file"), std::string::npos) << r.err;
  r = runEwaview("--synthetic sphere:16 --tour 4 --bookmarks " + (dir / "none.json").string() + out,
                 "tour");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("none.json: no such bookmarks file"), std::string::npos) << r.err;
  r = runEwaview("--synthetic sphere:16 --tour 4 --crop 0,5,0,5,0,5 --bookmarks " + one + out,
                 "tour");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--tour takes the crop box and planes of its bookmarks"), std::string::npos)
      << r.err;
  r = runEwaview("--synthetic sphere:16 --bookmarks " + one + out, "tour");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--bookmarks goes with --tour"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "f_0.png"));
}

}  // namespace
}  // namespace ewa::test
