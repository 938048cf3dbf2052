// The crop box and clipping planes in JSON: round trips through bookmarks and settings, and
// bad values refused (or, in the settings, dropped without losing the rest).
#include <gtest/gtest.h>

#include "io/camera_bookmarks.h"
#include "io/clip_region_json.h"
#include "io/viewer_settings.h"

namespace ewa {
namespace {

ClipRegion sampleRegion() {
  ClipRegion r;
  r.cropEnabled = true;
  r.cropMin = {1.5, -2, 3};
  r.cropMax = {10, 20.25, 30};
  r.planes.push_back({glm::dvec3(1, 2, 3), glm::dvec3(0, 0.6, -0.8), true});
  r.planes.push_back({glm::dvec3(-1, 0, 0), glm::dvec3(1, 0, 0), false});
  return r;
}

TEST(ClipJson, RoundTripsThroughBookmarksAndSettings) {
  CameraBookmark b;
  b.name = "inside";
  b.clip = sampleRegion();
  const std::vector<CameraBookmark> back = bookmarksFromJson(bookmarksToJson({b}), "marks");
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].clip, b.clip);
  // Bookmarks without a clip (older files) read as nothing clipped.
  CameraBookmark plain;
  plain.name = "plain";
  const std::string text = bookmarksToJson({plain});
  EXPECT_EQ(text.find("clip"), std::string::npos);
  EXPECT_EQ(bookmarksFromJson(text, "marks")[0].clip, ClipRegion{});

  ViewerSettings s;
  s.clip = sampleRegion();
  s.clipVolume = "/data/engine.nhdr";
  const ViewerSettings t = viewerSettingsFromJson(viewerSettingsToJson(s), "settings");
  EXPECT_EQ(t.clip, s.clip);
  EXPECT_EQ(t.clipVolume, s.clipVolume);
}

TEST(ClipJson, BadValuesAreRefused) {
  using nlohmann::json;
  const auto problem = [](const json& j) {
    try {
      clipRegionFromJson(j);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(problem(json::array()).find("must be a JSON object"), std::string::npos);
  EXPECT_NE(problem(json::parse(R"({"crop": {"enabled": true, "min": [0,0,5], "max": [1,1,1]}})"))
                .find("min must be less"),
            std::string::npos);
  EXPECT_NE(problem(json::parse(R"({"planes": [{"point": [0,0,0], "normal": [0,0,0]}]})"))
                .find("normal is zero"),
            std::string::npos);
  EXPECT_NE(problem(json::parse(R"({"planes": [{"point": [0,0], "normal": [0,0,1]}]})"))
                .find("3 numbers"),
            std::string::npos);
  EXPECT_NE(problem(json::parse(R"({"planes": "x"})")).find("must be a list"), std::string::npos);
  // In the settings a bad clip is dropped and the rest kept.
  const ViewerSettings s = viewerSettingsFromJson(
      R"({"window_size": [640, 480], "clip": {"planes": 3, "volume": "/x"}})", "settings");
  EXPECT_EQ(s.windowWidth, 640);
  EXPECT_EQ(s.clip, ClipRegion{});
  EXPECT_TRUE(s.clipVolume.empty());
}

}  // namespace
}  // namespace ewa
