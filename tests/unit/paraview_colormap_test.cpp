// Unit tests of the ParaView colour-map preset import: arrays, opacity, rescaling, bad files.
#include "io/paraview_colormap.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/transfer_function_io.h"

namespace ewa {
namespace {

const char* kTwoPresets = R"([
  {"Name": "Categorical", "IndexedColors": [1, 0, 0, 0, 1, 0]},
  {"Name": "Cool to Warm", "ColorSpace": "Diverging", "NanColor": [1, 1, 0],
   "RGBPoints": [-1, 0.23, 0.299, 0.754,  0, 0.865, 0.865, 0.865,  1, 0.706, 0.016, 0.15]},
  {"Name": "With opacity", "RGBPoints": [10, 0, 0, 0, 20, 1, 1, 1],
   "Points": [10, 0, 0.5, 0, 15, 0.2, 0.5, 0, 20, 1, 0.5, 0]}
])";

TEST(ParaViewImport, ReadsArraysSkipsIndexedMapsAndKeepsOpacity) {
  const auto maps = parseParaViewPresets(kTwoPresets, "presets.json");
  ASSERT_EQ(maps.size(), 2u);
  EXPECT_EQ(maps[0].name, "Cool to Warm");
  ASSERT_EQ(maps[0].color.size(), 3u);
  EXPECT_EQ(maps[0].color[1].value, 0.0);
  EXPECT_EQ(maps[0].color[2].rgb, glm::dvec3(0.706, 0.016, 0.15));
  EXPECT_TRUE(maps[0].opacity.empty());
  ASSERT_EQ(maps[1].opacity.size(), 3u);
  EXPECT_EQ(maps[1].opacity[1], (OpacityPoint{15.0, 0.2}));

  const auto single = parseParaViewPresets(R"({"RGBPoints": [0, 1, 0, 0, 1, 0, 0, 1]})", "one");
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(single[0].name, "preset 0");
}

TEST(ParaViewImport, RescalesOntoTheDataRangeOrKeepsValues) {
  const auto maps = parseParaViewPresets(kTwoPresets, "presets.json");
  TransferFunction current;
  current.opacity = {{0.0, 0.0}, {255.0, 0.7}};
  // Colour-only map: [-1, 1] stretched onto [0, 255]; the opacity stays.
  const TransferFunction cw = applyImportedColorMap(current, maps[0], 0.0, 255.0, true);
  EXPECT_EQ(cw.opacity, current.opacity);
  EXPECT_DOUBLE_EQ(cw.color[1].value, 127.5);
  EXPECT_NEAR(cw.colorAt(127.5).g, 0.865, 1e-12);
  EXPECT_NO_THROW(cw.validate());
  // With opacity: both functions move by the same map, [10, 20] -> [100, 200].
  const TransferFunction wo = applyImportedColorMap(current, maps[1], 100.0, 200.0, true);
  ASSERT_EQ(wo.opacity.size(), 3u);
  EXPECT_DOUBLE_EQ(wo.opacity[1].value, 150.0);
  EXPECT_DOUBLE_EQ(wo.alphaAt(150.0), 0.2);
  EXPECT_EQ(wo.colorAt(150.0), glm::dvec3(0.5));
  const TransferFunction kept = applyImportedColorMap(current, maps[1], 100.0, 200.0, false);
  EXPECT_DOUBLE_EQ(kept.opacity[1].value, 15.0);
}

// Each bad text fails with one line "<name>: ..." containing `needle`.
void expectError(const std::string& text, const std::string& needle) {
  try {
    parseParaViewPresets(text, "bad.json");
    ADD_FAILURE() << "no error for " << text;
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("bad.json: ", 0), 0u) << what;
    EXPECT_NE(what.find(needle), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(ParaViewImport, BadFilesGiveOneLineErrors) {
  expectError("{\"RGBPoints\": [0, 1, 0", "invalid JSON");
  expectError("42", "expected a ParaView preset");
  expectError("{\"Name\": \"x\"}", "no \"RGBPoints\"");
  expectError("[{\"IndexedColors\": [1, 0, 0]}]", "no preset with \"RGBPoints\"");
  expectError("[3]", "entry 0 is not an object");
  expectError("{\"RGBPoints\": [0, 1, 0, 0, 1, 0]}", "groups of 4");
  expectError("{\"RGBPoints\": []}", "groups of 4");
  expectError("{\"RGBPoints\": [0, 1, 0, \"red\"]}", "RGBPoints[3] is not a finite number");
  expectError("{\"RGBPoints\": [0, 1, 0, 2]}", "blue is 2, outside [0, 1]");
  expectError("{\"RGBPoints\": [0, 1, 0, 0], \"Points\": [0, 1.5, 0.5, 0]}",
              "opacity is 1.5, outside [0, 1]");
  expectError("{\"RGBPoints\": [0, 1, 0, 0], \"Points\": [0, 1]}", "Points must hold groups of 4");
  expectError("{\"RGBPoints\": \"viridis\"}", "must be an array of numbers");
}

TEST(ParaViewImport, MissingFileAndDirectoryNameThePath) {
  const std::string dir = ::testing::TempDir();
  EXPECT_THROW(
      {
        try {
          loadParaViewPresets(dir);
        } catch (const std::runtime_error& e) {
          EXPECT_EQ(std::string(e.what()).rfind(dir + ": is a directory", 0), 0u) << e.what();
          throw;
        }
      },
      std::runtime_error);
  const std::string missing = dir + "/no_such_preset.json";
  EXPECT_THROW(loadParaViewPresets(missing), std::runtime_error);
  const std::string path = dir + "/ewa_pv_preset.json";
  std::ofstream(path) << kTwoPresets;
  EXPECT_EQ(loadParaViewPresets(path).size(), 2u);
  std::filesystem::remove(path);
}

TEST(ParaViewImport, ShippedExampleLoadsAndGivesValidFunctions) {
  const auto maps =
      loadParaViewPresets(std::string(EWA_TEST_DIR) + "/../assets/presets/paraview_example.json");
  ASSERT_EQ(maps.size(), 3u);
  EXPECT_EQ(maps[1].name, "Black-Body Radiation");
  EXPECT_EQ(maps[2].opacity.size(), 3u);
  for (const auto& map : maps) {
    const TransferFunction tf = applyImportedColorMap({}, map, -1024.0, 3071.0, true);
    EXPECT_NO_THROW(tf.validate());
    EXPECT_DOUBLE_EQ(tf.color.front().value, -1024.0);
    EXPECT_DOUBLE_EQ(tf.color.back().value, 3071.0);
  }
}

// A JSON file dropped on the window: ewaview's own format first, else a ParaView preset file.
TEST(ParaViewImport, ADroppedFileIsOurFunctionOrAParaViewPreset) {
  const std::string dir = ::testing::TempDir();
  TransferFunction current;
  current.addOpacityPoint(0.0, 0.0);
  current.addOpacityPoint(100.0, 0.5);
  TransferFunction own = current;
  own.addColorPoint(50.0, {1.0, 0.0, 0.0});
  const std::string ownPath = dir + "/ewa_dropped.tf.json";
  saveTransferFunction(ownPath, own);
  std::string what;
  EXPECT_EQ(loadTransferFunctionOrPreset(ownPath, current, 0.0, 100.0, &what), own);
  EXPECT_EQ(what, "loaded " + ownPath);

  const std::string paraview = dir + "/ewa_dropped_pv.json";
  std::ofstream(paraview) << kTwoPresets;
  const TransferFunction imported =
      loadTransferFunctionOrPreset(paraview, current, 0.0, 100.0, &what);
  EXPECT_EQ(imported, applyImportedColorMap(current, parseParaViewPresets(kTwoPresets, "x")[0], 0.0,
                                            100.0, true));
  EXPECT_EQ(what, "imported \"Cool to Warm\" from " + paraview);

  // Neither: the error is our own format's, naming the file.
  const std::string bad = dir + "/ewa_dropped_bad.json";
  std::ofstream(bad) << "{\"opacity\": 3}";
  try {
    loadTransferFunctionOrPreset(bad, current, 0.0, 100.0, &what);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(bad + ": ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("opacity"), std::string::npos) << e.what();
  }
  for (const std::string& f : {ownPath, paraview, bad}) std::filesystem::remove(f);
}

}  // namespace
}  // namespace ewa
