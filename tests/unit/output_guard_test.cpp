// Writers never replace an input: a saved volume, its MetaImage data file or a picture that names
// a file the volume was read from is refused, and a header and its data are replaced as a pair.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <string>
#include <thread>

#include "io/atomic_file.h"
#include "io/volume_loader.h"
#include "io/volume_writer.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

Volume ramp(int64_t nx, int64_t ny, int64_t nz, int first) {
  std::vector<uint8_t> bytes(size_t(nx * ny * nz));
  for (size_t n = 0; n < bytes.size(); ++n) bytes[n] = uint8_t(first + n);
  return Volume({nx, ny, nz}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8,
                std::move(bytes));
}

std::string mhd(const std::string& data, int64_t nz) {
  return "ObjectType = Image\nNDims = 3\nDimSize = 4 4 " + std::to_string(nz) +
         "\nElementType = MET_UCHAR\nElementDataFile = " + data + "\n";
}

void expectRefused(const std::function<void()>& write, const std::string& fragment) {
  try {
    write();
    ADD_FAILURE() << "expected a refusal containing: " << fragment;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(OutputGuard, AVolumeRemembersEveryFileItWasReadFrom) {
  TempDir dir;
  const std::string data = dir.write("scan.raw", std::string(64, '\7'));
  const std::string header = dir.write("scan.mhd", mhd("scan.raw", 4));
  const Volume v = loadVolume(header);
  ASSERT_EQ(v.sourceFiles().size(), 2u);
  EXPECT_EQ(v.sourceFiles()[0], header);
  EXPECT_EQ(v.sourceFiles()[1], data);
}

TEST(OutputGuard, SavingAPairWhoseDataFileIsTheInputsIsRefusedAndTheInputKept) {
  TempDir dir;
  const std::string input = std::string(64, '\7');
  dir.write("scan.raw", input);
  const std::string header = dir.write("in.mhd", mhd("scan.raw", 4));
  const Volume v = loadVolume(header);
  // scan.mhd's data file would be scan.raw, the input's own: a second name is taken.
  writeVolume(dir.path("scan.mhd"), v);
  EXPECT_EQ(readTextFile(dir.path("scan.raw")), input) << "the input's data is untouched";
  EXPECT_EQ(metaImageDataFileOf(dir.path("scan.mhd")), dir.path("scan.1.raw"));
  EXPECT_EQ(loadVolume(dir.path("scan.mhd")).bytes(), v.bytes());
  // Naming the input itself, or its data file through another spelling, is refused.
  expectRefused([&] { writeVolume(header, v); }, "is an input file");
  fs::create_symlink(dir.path("scan.raw"), dir.path("alias.nii"));
  expectRefused([&] { writeVolume(dir.path("alias.nii"), v); }, "is an input file");
  EXPECT_EQ(readTextFile(dir.path("scan.raw")), input);
}

TEST(OutputGuard, APairIsReplacedThroughAFreshDataNameAndTheOldDataRemoved) {
  TempDir dir;
  const std::string path = dir.path("out.mhd");
  writeVolume(path, ramp(4, 4, 4, 0));
  EXPECT_EQ(metaImageDataFileOf(path), dir.path("out.raw"));
  writeVolume(path, ramp(4, 4, 2, 9));
  EXPECT_EQ(metaImageDataFileOf(path), dir.path("out.1.raw"));
  EXPECT_FALSE(fs::exists(dir.path("out.raw"))) << "the old pair's data goes once replaced";
  EXPECT_EQ(loadVolume(path).bytes(), ramp(4, 4, 2, 9).bytes());
  writeVolume(path, ramp(4, 4, 3, 5));
  EXPECT_EQ(metaImageDataFileOf(path), dir.path("out.raw"));
  EXPECT_FALSE(fs::exists(dir.path("out.1.raw")));
  EXPECT_EQ(loadVolume(path).bytes(), ramp(4, 4, 3, 5).bytes());
}

// A writer killed at any moment leaves a pair that loads as one of the two volumes: the two
// volumes differ in size, so a header beside the other write's data would not load.
TEST(OutputGuard, AKilledWriterLeavesTheOldPairOrTheNewNeverAMix) {
  TempDir dir;
  const std::string path = dir.path("pair.mhd");
  const Volume a = ramp(128, 128, 64, 1), b = ramp(128, 128, 40, 2);
  writeVolume(path, a);
  std::mt19937 random(7);
  int killedMidway = 0;
  for (int round = 0; round < 24; ++round) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      for (int n = 0;; ++n) writeVolume(path, n % 2 ? a : b);
    }
    std::this_thread::sleep_for(std::chrono::microseconds(2000 + random() % 20000));
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    killedMidway += WIFSIGNALED(status);
    const Volume v = loadVolume(path);
    EXPECT_TRUE(v.bytes() == a.bytes() || v.bytes() == b.bytes()) << "round " << round;
  }
  EXPECT_EQ(killedMidway, 24);
}

}  // namespace
}  // namespace ewa
