// Unit tests of transfer-function JSON: round trip, defaults, and one-line errors naming the file.
#include "io/transfer_function_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace ewa {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class TransferFunctionIo : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) / (std::string("ewa_tf_io_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

  // Loading `text` fails with one line that starts with the path and contains `needle`.
  void expectLoadError(const std::string& text, const std::string& needle) {
    const std::string path = write("bad.json", text);
    try {
      loadTransferFunction(path);
      ADD_FAILURE() << "no error for " << text;
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(needle), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }

  fs::path dir_;
};

TEST_F(TransferFunctionIo, SaveThenLoadIsExact) {
  TransferFunction tf;
  tf.opacity = {{-1000.0, 0.0}, {0.1, 1.0 / 3.0}, {2.5e7, 1.0}};
  tf.color = {{-3.0, {0.1, 0.2, 0.3}}, {7.0 / 3.0, {1.0, 2.0 / 3.0, 0.0}}};
  tf.opacityUnitDistance = 0.859375;
  const std::string path = (dir_ / "tf.json").string();
  saveTransferFunction(path, tf);
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  const TransferFunction back = loadTransferFunction(path);
  EXPECT_EQ(back, tf);
  // Saving again over the file works too.
  tf.opacityUnitDistance = 2.0;
  saveTransferFunction(path, tf);
  EXPECT_EQ(loadTransferFunction(path), tf);
}

TEST_F(TransferFunctionIo, EmptyListsRoundTrip) {
  const std::string path = (dir_ / "empty.json").string();
  saveTransferFunction(path, TransferFunction());
  EXPECT_EQ(loadTransferFunction(path), TransferFunction());
}

TEST_F(TransferFunctionIo, ParsesDefaultsAndSorts) {
  const TransferFunction tf = parseTransferFunctionJson(
      R"({"name": "x", "opacity": [[10, 0.5], [0, 0]], "color": [[1, 1, 0, 0]]})", "inline");
  ASSERT_EQ(tf.opacity.size(), 2u);
  EXPECT_EQ(tf.opacity[0].value, 0.0);
  EXPECT_EQ(tf.opacity[1].alpha, 0.5);
  EXPECT_EQ(tf.color[0].rgb, glm::dvec3(1.0, 0.0, 0.0));
  EXPECT_EQ(tf.opacityUnitDistance, 1.0);
  EXPECT_DOUBLE_EQ(tf.alphaAt(5.0), 0.25);
}

TEST_F(TransferFunctionIo, SaveRejectsInvalidAndLeavesNoFile) {
  TransferFunction tf;
  tf.opacity = {{0.0, 2.0}};
  const std::string path = (dir_ / "invalid.json").string();
  try {
    saveTransferFunction(path, tf);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST_F(TransferFunctionIo, MissingFileAndDirectoryNameThePath) {
  const std::string missing = (dir_ / "nope.json").string();
  try {
    loadTransferFunction(missing);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(missing + ": ", 0), 0u) << e.what();
  }
  EXPECT_THROW(loadTransferFunction(dir_.string()), std::runtime_error);
}

TEST_F(TransferFunctionIo, MalformedFilesGiveOneLineErrors) {
  expectLoadError("{\"opacity\": [[0, 0],\n]}", "line 2");
  expectLoadError("", "invalid JSON");
  expectLoadError("[1, 2]", "object");
  expectLoadError(R"({"color": []})", "missing \"opacity\"");
  expectLoadError(R"({"opacity": 3})", "\"opacity\" must be an array");
  expectLoadError(R"({"opacity": [[0, 0, 0]]})", "opacity[0] must be [value, alpha]");
  expectLoadError(R"({"opacity": [[0, "a"]]})", "opacity[0][1] must be a number");
  expectLoadError(R"({"opacity": [[0, true]]})", "must be a number");
  expectLoadError(R"({"opacity": [[0, 0], [1, 1.5]]})", "alpha 1.5 is outside [0, 1]");
  expectLoadError(R"({"opacity": [], "color": [[0, 1, 0]]})", "color[0] must be [value, r, g, b]");
  expectLoadError(R"({"opacity": [], "color": [[0, 1, 0, -1]]})", "outside [0, 1]");
  expectLoadError(R"({"opacity": [], "opacity_unit_distance": 0})", "unit distance");
  expectLoadError(R"({"opacity": [], "opacity_unit_distance": "1"})", "must be a number");
  expectLoadError(R"({"opacity": [], "opacity_unit_distanse": 1})", "unknown key");
  expectLoadError(R"({"opacity": [[1e400, 0]]})", "invalid JSON");
}

TEST_F(TransferFunctionIo, ParseErrorsUseTheGivenName) {
  try {
    parseTransferFunctionJson("{", "preset 'bone'");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("preset 'bone': invalid JSON", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace ewa
