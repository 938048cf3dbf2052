// VolumeSaveJob (the window's "Save volume"): the NRRD it writes reads back as the same volume,
// its transfer function is the sidecar the file reopens with, and a failure is one line.
#include "ui/volume_save_job.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "core/synthetic_volume.h"
#include "io/transfer_function_io.h"
#include "io/volume_loader.h"

namespace ewa {
namespace {

namespace fs = std::filesystem;

// Polls like the window does, once a frame, until the job is done (at most 60 s).
bool waitFor(VolumeSaveJob& job, std::string* text, bool* failed) {
  for (int n = 0; n < 6000; ++n) {
    if (job.poll(text, failed)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

fs::path scratchFolder(const std::string& name) {
  const fs::path dir = fs::path(EWA_TEST_OUT) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(VolumeSaveJob, WritesTheVolumeAndItsTransferFunctionBesideIt) {
  SyntheticVolume s = makeSyntheticVolume("sphere:24");
  s.volume.setSpacing({0.5, 0.75, 2.0});
  TransferFunction tf;
  tf.addOpacityPoint(s.volume.minValue(), 0.0);
  tf.addColorPoint(s.volume.maxValue(), {1.0, 0.5, 0.25});
  tf.addOpacityPoint(0.5 * (s.volume.minValue() + s.volume.maxValue()), 0.25);  // an edit
  const auto volume = std::make_shared<const Volume>(std::move(s.volume));
  const fs::path path = scratchFolder("save_job") / "sphere.nrrd";

  VolumeSaveJob job;
  std::string text;
  bool failed = true;
  EXPECT_FALSE(job.poll(&text, &failed));  // nothing started
  job.start(volume, tf, path.string());
  EXPECT_TRUE(job.running());
  ASSERT_TRUE(waitFor(job, &text, &failed));
  EXPECT_FALSE(failed) << text;
  EXPECT_FALSE(job.running());
  EXPECT_NE(text.find("saved " + path.string()), std::string::npos) << text;
  EXPECT_NE(text.find("sphere.tf.json"), std::string::npos) << text;

  const Volume back = loadVolume(path.string());
  EXPECT_EQ(back.dims(), volume->dims());
  EXPECT_EQ(back.spacing(), volume->spacing());
  EXPECT_EQ(back.type(), volume->type());
  EXPECT_EQ(back.bytes(), volume->bytes());
  const std::string sidecar = sidecarTransferFunctionPath(path.string());
  EXPECT_EQ(sidecar, (path.parent_path() / "sphere.tf.json").string());
  EXPECT_EQ(loadTransferFunction(sidecar), tf);

  // Only a crop box's voxels: the range of them, at their places.
  const fs::path part = path.parent_path() / "part.nrrd";
  job.start(volume, tf, part.string(), VoxelRange{{2, 3, 4}, {20, 9, 4}});
  ASSERT_TRUE(waitFor(job, &text, &failed));
  EXPECT_FALSE(failed) << text;
  const Volume cut = loadVolume(part.string());
  ASSERT_EQ(cut.dims(), (std::array<int64_t, 3>{19, 7, 1}));
  EXPECT_EQ(cut.value(5, 6, 0), volume->value(7, 9, 4));
  EXPECT_EQ(cut.origin(), volume->worldPosition(2, 3, 4));
}

TEST(VolumeSaveJob, AFolderThatIsNotThereIsOneLineNamingTheFile) {
  const auto volume = std::make_shared<const Volume>(makeSyntheticVolume("sphere:8").volume);
  const fs::path path = scratchFolder("save_job_missing") / "no" / "such" / "v.nrrd";
  VolumeSaveJob job;
  job.start(volume, TransferFunction{}, path.string());
  std::string text;
  bool failed = false;
  ASSERT_TRUE(waitFor(job, &text, &failed));
  EXPECT_TRUE(failed);
  EXPECT_EQ(text.find('\n'), std::string::npos) << text;
  EXPECT_NE(text.find(path.string()), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(path));
}

}  // namespace
}  // namespace ewa
