// Unit tests of the viewer's files: settings, camera bookmarks, atomic writes, the file listing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

#include "io/atomic_file.h"
#include "io/camera_bookmarks.h"
#include "io/file_listing.h"
#include "io/frame_names.h"
#include "io/viewer_settings.h"
#include "render/renderer.h"

namespace ewa {
namespace {

namespace fs = std::filesystem;

// A fresh scratch folder per test, removed afterwards.
class ViewerFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ewa_unit_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(ViewerFiles, AtomicWriteReplacesAndLeavesNoTemporary) {
  const std::string p = path("sub/a.txt");
  EXPECT_THROW(writeFileAtomically(p, "x"), std::runtime_error);  // no folder, not asked to make it
  writeFileAtomically(p, "first", true);
  writeFileAtomically(p, "second");
  EXPECT_EQ(readTextFile(p), "second");
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "sub")) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
  EXPECT_THROW(readTextFile(path("missing")), std::runtime_error);
}

TEST_F(ViewerFiles, SettingsRoundTripAndDefaults) {
  const std::string p = path("cfg/settings.json");
  EXPECT_EQ(loadViewerSettings(p).windowWidth, ViewerSettings().windowWidth);  // missing file
  ViewerSettings s;
  s.windowWidth = 640;
  s.windowHeight = 480;
  s.recentFiles = {"/a/b.nrrd", "/c.vti"};
  s.lastTransferFunction = "/t/bone.tf.json";
  s.filter = FilterMode::Swan;
  s.renderMode = "xray";
  s.cutoff = 9.0;
  s.kernelWidth = 0.8;
  s.classification = "post";
  s.slabThickness = 2.5;
  s.prefilter = 0.125;
  s.background = {0.1, 0.2, 0.3};
  s.levelOfDetail = false;
  s.axes = false;
  s.captureScale = 3;
  saveViewerSettings(p, s);
  const ViewerSettings r = loadViewerSettings(p);
  EXPECT_EQ(r.captureScale, 3);
  EXPECT_EQ(r.windowWidth, 640);
  EXPECT_EQ(r.windowHeight, 480);
  EXPECT_EQ(r.recentFiles, s.recentFiles);
  EXPECT_EQ(r.lastTransferFunction, s.lastTransferFunction);
  EXPECT_EQ(r.filter, FilterMode::Swan);
  EXPECT_EQ(r.renderMode, "xray");
  EXPECT_EQ(r.cutoff, 9.0);
  EXPECT_EQ(r.kernelWidth, 0.8);
  EXPECT_EQ(r.classification, "post");
  EXPECT_EQ(r.slabThickness, 2.5);
  EXPECT_EQ(r.prefilter, 0.125);
  EXPECT_EQ(r.background, s.background);
  EXPECT_FALSE(r.levelOfDetail);
  EXPECT_FALSE(r.axes);
  EXPECT_EQ(r.depthCutoff, 1.0);
  EXPECT_EQ(r.postNormals, "ray");
  s.postNormals = "voxel";
  saveViewerSettings(p, s);
  EXPECT_EQ(loadViewerSettings(p).postNormals, "voxel");
  EXPECT_TRUE(r.coarseSlabs);
  s.coarseSlabs = false;  // saved as "slab_resolution": "full"
  saveViewerSettings(p, s);
  EXPECT_FALSE(loadViewerSettings(p).coarseSlabs);
  // The uncut depth profile is saved as "inf" (JSON has no infinity) and read back.
  s.depthCutoff = INFINITY;
  saveViewerSettings(p, s);
  EXPECT_TRUE(std::isinf(loadViewerSettings(p).depthCutoff));
  s.depthCutoff = 2.25;
  saveViewerSettings(p, s);
  EXPECT_EQ(loadViewerSettings(p).depthCutoff, 2.25);
}

// A first run (no settings file) and a settings file without a "render" part must give the
// renderer's own defaults, not older ones.
TEST_F(ViewerFiles, SettingsDefaultsAreTheRenderersDefaults) {
  const RenderSettings render;
  const ViewerSettings fresh;
  EXPECT_EQ(fresh.filter, render.filter);
  EXPECT_EQ(render.mode, RenderMode::Composite);
  EXPECT_EQ(fresh.renderMode, "composite");
  EXPECT_EQ(fresh.cutoff, render.cutoff);
  EXPECT_EQ(fresh.depthCutoff, render.depthCutoff);
  EXPECT_EQ(fresh.postNormals, "ray");  // unit tests link no renderer: its name spelt out
  EXPECT_EQ(render.postNormals, PostNormals::Ray);
  EXPECT_EQ(fresh.kernelWidth, render.kernelWidth);
  EXPECT_EQ(fresh.classification, classificationModeName(render.classification.mode));
  EXPECT_EQ(fresh.slabThickness, render.slabThickness);
  EXPECT_EQ(fresh.coarseSlabs, render.coarseSlabs);
  EXPECT_EQ(fresh.prefilter, render.classification.prefilter);
  EXPECT_EQ(fresh.background, render.background);
  const std::string p = path("partial/settings.json");
  std::filesystem::create_directories(std::filesystem::path(p).parent_path());
  std::ofstream(p) << R"({"render": {"mode": "mip"}})";
  const ViewerSettings partial = loadViewerSettings(p);
  EXPECT_EQ(partial.renderMode, "mip");
  EXPECT_EQ(partial.slabThickness, render.slabThickness);
  EXPECT_EQ(partial.cutoff, render.cutoff);
  EXPECT_TRUE(partial.axes);  // the window shows the axes unless switched off
}

TEST_F(ViewerFiles, SettingsClampOddValuesAndRejectBadJson) {
  const ViewerSettings s = viewerSettingsFromJson(
      R"({"window_size":[1,99999],"render":{"cutoff":1000,"depth_cutoff":0.01,"kernel_width":0.01,"mode":"weird","filter":"blurry",
          "background":[2,-1,0.5],"prefilter":7},"unknown":1})",
      "s.json");
  EXPECT_EQ(s.windowWidth, 64);
  EXPECT_EQ(s.windowHeight, 16384);
  EXPECT_EQ(viewerSettingsFromJson(R"({"capture_scale": 9})", "s.json").captureScale, 4);
  EXPECT_EQ(viewerSettingsFromJson(R"({"capture_scale": 0})", "s.json").captureScale, 1);
  EXPECT_EQ(s.cutoff, 64.0);
  EXPECT_EQ(s.depthCutoff, 0.25);
  EXPECT_EQ(s.kernelWidth, 0.3);
  EXPECT_EQ(s.prefilter, kMaxPrefilter);
  EXPECT_EQ(s.renderMode, "composite");
  EXPECT_EQ(s.filter, FilterMode::Ewa);
  EXPECT_EQ(s.background, glm::dvec3(1.0, 0.0, 0.5));
  try {
    viewerSettingsFromJson("{not json", "s.json");
    FAIL() << "no throw";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("s.json: ", 0), 0u) << e.what();
  }
  EXPECT_THROW(viewerSettingsFromJson(R"({"recent_files": 3})", "s.json"), std::runtime_error);
}

TEST_F(ViewerFiles, RecentFilesMoveToFrontWithoutDuplicatesAndStayBounded) {
  std::vector<std::string> recent;
  for (int n = 0; n < 15; ++n) addRecentFile(recent, "f" + std::to_string(n));
  EXPECT_EQ(recent.size(), ViewerSettings::kMaxRecentFiles);
  EXPECT_EQ(recent.front(), "f14");
  addRecentFile(recent, "f10");
  EXPECT_EQ(recent.front(), "f10");
  EXPECT_EQ(std::count(recent.begin(), recent.end(), "f10"), 1);
  EXPECT_EQ(recent.size(), ViewerSettings::kMaxRecentFiles);
}

TEST_F(ViewerFiles, ConfigDirFollowsEnvironment) {
  // This process only (CTest runs each test alone), restored at the end all the same.
  const char* saved = std::getenv("EWAVIEW_CONFIG_DIR");
  const std::string keep = saved ? saved : "";
  const char* savedXdg = std::getenv("XDG_CONFIG_HOME");
  const std::string keepXdg = savedXdg ? savedXdg : "";
  ::setenv("EWAVIEW_CONFIG_DIR", "/tmp/ewa-cfg-test", 1);
  EXPECT_EQ(defaultConfigDir(), "/tmp/ewa-cfg-test");
  ::unsetenv("EWAVIEW_CONFIG_DIR");
  ::setenv("XDG_CONFIG_HOME", "/tmp/xdg", 1);
  EXPECT_EQ(defaultConfigDir(), "/tmp/xdg/ewaview");
  if (saved) ::setenv("EWAVIEW_CONFIG_DIR", keep.c_str(), 1);
  if (savedXdg)
    ::setenv("XDG_CONFIG_HOME", keepXdg.c_str(), 1);
  else
    ::unsetenv("XDG_CONFIG_HOME");
  EXPECT_EQ(settingsPathIn("/c"), "/c/settings.json");
  EXPECT_EQ(imguiIniPathIn("/c"), "/c/imgui.ini");
}

TEST_F(ViewerFiles, BookmarksBesideTheVolumeRoundTrip) {
  EXPECT_EQ(bookmarksPathFor("/data/engine/engine.nhdr"), "/data/engine/engine.bookmarks.json");
  const std::string fb1 = fallbackBookmarksPath("/data/a/engine.nhdr", "/cfg");
  const std::string fb2 = fallbackBookmarksPath("/data/b/engine.nhdr", "/cfg");
  EXPECT_EQ(fb1.rfind("/cfg/bookmarks/engine.", 0), 0u) << fb1;
  EXPECT_NE(fb1, fb2);  // same name in two folders: two files
  const std::string p = bookmarksPathFor(path("vol.nrrd"));
  EXPECT_TRUE(loadBookmarks(p).empty());  // no file yet
  CameraBookmark a{"front", Camera{}, ClipRegion{}};
  a.camera.position = {1, 2, 3};
  a.camera.focalPoint = {4, 5, 6.5};
  a.camera.viewUp = {0, 0, 1};
  a.camera.viewAngleDeg = 22.5;
  a.camera.orthographic = true;
  CameraBookmark b{"side", Camera{}, ClipRegion{}};
  saveBookmarks(p, {a, b});
  const auto r = loadBookmarks(p);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].name, "front");
  EXPECT_EQ(r[0].camera.position, a.camera.position);
  EXPECT_EQ(r[0].camera.focalPoint, a.camera.focalPoint);
  EXPECT_EQ(r[0].camera.viewUp, a.camera.viewUp);
  EXPECT_EQ(r[0].camera.viewAngleDeg, 22.5);
  EXPECT_TRUE(r[0].camera.orthographic);
  EXPECT_EQ(r[1].name, "side");
}

// Where the window (and --tour) reads a volume's bookmarks: beside it unless only the settings
// folder's copy exists; a synthetic volume's only there, named after it.
TEST_F(ViewerFiles, BookmarkPlacesPreferBesideUnlessOnlyTheFallbackExists) {
  const std::string volume = path("places.nrrd"), config = path("cfg_places");
  const BookmarkPlaces places = bookmarkPlaces(volume, "places.nrrd", config);
  EXPECT_EQ(places.beside, bookmarksPathFor(volume));
  EXPECT_EQ(places.fallback, fallbackBookmarksPath(volume, config));
  EXPECT_EQ(places.read(), places.beside);  // neither exists: beside, where they are written
  CameraBookmark mark{"m", Camera{}, ClipRegion{}};
  saveBookmarks(places.fallback, {mark}, true);
  EXPECT_EQ(places.read(), places.fallback);  // only the fallback exists
  saveBookmarks(places.beside, {mark, mark});
  EXPECT_EQ(places.read(), places.beside);  // both: beside
  const BookmarkPlaces synthetic = bookmarkPlaces("", "sphere:16", config);
  EXPECT_TRUE(synthetic.beside.empty());
  EXPECT_EQ(synthetic.fallback, fallbackBookmarksPath("synthetic-sphere:16", config));
  EXPECT_EQ(synthetic.read(), synthetic.fallback);
  EXPECT_TRUE(bookmarkPlaces("", "sphere:16", "").read().empty());  // nowhere to keep them
  // As tour stops: the views and clip regions in order.
  mark.camera.position = {7, 8, 9};
  mark.clip.cropEnabled = true;
  const std::vector<TourStop> stops = tourStopsOf({CameraBookmark{}, mark});
  ASSERT_EQ(stops.size(), 2u);
  EXPECT_EQ(stops[1].camera.position, glm::dvec3(7, 8, 9));
  EXPECT_TRUE(stops[1].clip.cropEnabled);
}

TEST_F(ViewerFiles, BadBookmarksThrowNamingTheFile) {
  EXPECT_THROW(bookmarksFromJson("[]", "b.json"), std::runtime_error);
  const std::string degenerate =
      R"({"bookmarks":[{"name":"x","position":[0,0,0],"focal_point":[0,0,0],"view_up":[0,1,0]}]})";
  try {
    bookmarksFromJson(degenerate, "b.json");
    FAIL() << "no throw";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "b.json: bookmark 'x' is not a valid camera");
  }
}

TEST_F(ViewerFiles, ListingShowsFoldersThenVolumeFiles) {
  fs::create_directories(dir_ / "zdir");
  fs::create_directories(dir_ / ".hidden");
  for (const char* name : {"b.NRRD", "a.vti", "notes.txt", "c.mha", ".x.nrrd"})
    std::ofstream(path(name)) << "1234";
  const auto entries = listDirectory(dir_.string(), volumeFileExtensions());
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries[0].name, "zdir");
  EXPECT_TRUE(entries[0].directory);
  EXPECT_EQ(entries[1].name, "a.vti");
  EXPECT_EQ(entries[1].size, 4u);
  EXPECT_EQ(entries[2].name, "b.NRRD");  // extensions match case-insensitively
  EXPECT_EQ(entries[3].name, "c.mha");
  EXPECT_EQ(listDirectory(dir_.string(), {}, true).size(), 7u);  // everything, hidden too
  EXPECT_THROW(listDirectory(path("nope"), {}), std::runtime_error);
  EXPECT_TRUE(hasExtension("x/y.NHDR", volumeFileExtensions()));
  EXPECT_FALSE(hasExtension("x/y.raw", volumeFileExtensions()));
}

TEST_F(ViewerFiles, ListingFindsDicomFilesWithoutExtensionsByTheirContent) {
  const std::string part10 = std::string(128, '\0') + "DICM" + std::string(16, '\0');
  const std::string element = std::string("\x08\x00\x10\x00\x04\x00\x00\x00", 8) + "abcd";
  const std::string bare = element + std::string("\x08\x00\x20\x00\x04\x00\x00\x00", 8) + "abcd";
  for (const auto& [name, bytes] : std::vector<std::pair<std::string, std::string>>{
           {"IM0001", part10},
           {"1.2.840.113619.2.55", part10},
           {"ACRNEMA", bare},
           {"head.acr", bare},
           {"README", "a text that is no DICOM file, long enough to be looked into....."},
           {"notes.txt", part10},  // an extension of words: not looked into
           {"short", "DICM"}}) {
    std::ofstream(path(name), std::ios::binary) << bytes;
  }
  std::vector<std::string> names;
  for (const DirEntry& e : listDirectory(dir_.string(), volumeFileExtensions(), false, true))
    names.push_back(e.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"1.2.840.113619.2.55", "ACRNEMA", "IM0001", "head.acr"}));
  EXPECT_TRUE(listDirectory(dir_.string(), volumeFileExtensions()).empty());  // by name only
  EXPECT_TRUE(mayBeDicomByName("IM0001"));
  EXPECT_TRUE(mayBeDicomByName("1.3.12.2.1107"));
  EXPECT_TRUE(mayBeDicomByName("OLD.NEMA"));
  EXPECT_FALSE(mayBeDicomByName("scan.raw"));
  EXPECT_FALSE(mayBeDicomByName("scan."));
}

TEST_F(ViewerFiles, TurntableNamesFromPatternOrFolder) {
  const FrameNaming pat = parseFrameNaming("out/t_%03d.png");
  EXPECT_TRUE(pat.pattern);
  EXPECT_EQ(frameFileName(pat, 7, 36), "out/t_007.png");
  EXPECT_EQ(frameFileName(parseFrameNaming("a%%_%d.PNG"), 12, 36), "a%_12.PNG");
  const FrameNaming folder = parseFrameNaming("frames");
  EXPECT_FALSE(folder.pattern);
  EXPECT_EQ(frameFileName(folder, 5, 36), "frames/frame_005.png");
  EXPECT_EQ(frameFileName(folder, 5, 2000), "frames/frame_0005.png");
  for (const char* bad : {"t_%s.png", "t_%d_%d.png", "t_%d.jpg", "t_%.png", "t_%0123456d.png"})
    EXPECT_THROW(parseFrameNaming(bad), std::invalid_argument) << bad;
}

TEST_F(ViewerFiles, ScreenshotNamesAreTimestampedAndNeverOverwrite) {
  std::tm t{};
  t.tm_year = 2026 - 1900;
  t.tm_mon = 10;
  t.tm_mday = 21;
  t.tm_hour = 17;
  t.tm_min = 5;
  t.tm_sec = 9;
  t.tm_isdst = -1;
  const std::time_t when = std::mktime(&t);
  const std::string first = screenshotFileName(dir_.string(), "my vol.nhdr", when);
  EXPECT_EQ(first, path("ewaview-my_vol-20261121-170509.png"));
  std::ofstream(first) << "x";
  EXPECT_EQ(screenshotFileName(dir_.string(), "my vol.nhdr", when),
            path("ewaview-my_vol-20261121-170509-2.png"));
  // The same rule for any name: the window's "Save volume" offers NAME.nrrd, else NAME-2.nrrd...
  EXPECT_EQ(unusedFileName(dir_.string(), "head", ".nrrd"), path("head.nrrd"));
  std::ofstream(path("head.nrrd")) << "x";
  std::ofstream(path("head-2.nrrd")) << "x";
  EXPECT_EQ(unusedFileName(dir_.string(), "head", ".nrrd"), path("head-3.nrrd"));
  // Names promised to files not written yet (the window's queued screenshots) are passed over
  // too.
  const std::vector<std::string> promised = {path("ewaview-my_vol-20261121-170509-2.png"),
                                             path("ewaview-my_vol-20261121-170509-3.png")};
  const auto taken = [&](const std::string& p) {
    return std::find(promised.begin(), promised.end(), p) != promised.end();
  };
  EXPECT_EQ(screenshotFileName(dir_.string(), "my vol.nhdr", when, taken),
            path("ewaview-my_vol-20261121-170509-4.png"));
  EXPECT_EQ(unusedFileName(dir_.string(), "head", ".nrrd", taken), path("head-3.nrrd"));
}

}  // namespace
}  // namespace ewa
