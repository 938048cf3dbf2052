// --tf-preset: presets applied in order to the function the volume opens with, the same
// picture as that function written out and given with --tf.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/scene.h"
#include "cli_run.h"
#include "core/transfer_function_presets.h"
#include "image_compare.h"
#include "io/png_io.h"
#include "io/transfer_function_io.h"

namespace ewa::test {
namespace {

TEST(TfPresetCli, PresetsApplyInOrderToTheFunctionTheVolumeOpensWith) {
  const std::string dir = testOutputDir() + "/tf_preset";
  std::filesystem::create_directories(dir);
  const std::string volume = defaultVolumePath();
  // What the presets make of the default volume's own function (its sidecar or histogram's).
  Options o;
  o.file = volume;
  const Scene scene = loadScene(o);
  const double lo = scene.volume.minValue(), hi = scene.volume.maxValue();
  const TransferFunction expected = applyTransferFunctionPreset(
      applyTransferFunctionPreset(scene.transferFunction, "mr", lo, hi), "inferno", lo, hi);
  saveTransferFunction(dir + "/expected.tf.json", expected);

  const std::string size = " --resolution 64,64 -o ";
  CliRun r =
      runEwaview("--tf-preset mr --tf-preset inferno " + volume + size + dir + "/preset.png");
  ASSERT_EQ(r.code, 0) << r.err;
  r = runEwaview(volume + " --tf " + dir + "/expected.tf.json" + size + dir + "/file.png");
  ASSERT_EQ(r.code, 0) << r.err;
  r = runEwaview(volume + size + dir + "/plain.png");
  ASSERT_EQ(r.code, 0) << r.err;
  const Image8 preset = readPng(dir + "/preset.png");
  EXPECT_EQ(maxDifference(preset, readPng(dir + "/file.png")), 0);
  EXPECT_GT(maxDifference(preset, readPng(dir + "/plain.png")), 40);  // the presets changed it
  // The other order ends in MR's colours: another picture.
  r = runEwaview(volume + " --tf-preset inferno --tf-preset mr" + size + dir + "/reversed.png");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GT(maxDifference(preset, readPng(dir + "/reversed.png")), 40);

  r = runEwaview(volume + " --tf-preset bone" + size + dir + "/bad.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--tf-preset: bone not in {ct-bone,"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ewa::test
