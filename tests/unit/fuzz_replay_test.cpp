// Replays every fuzz target's seeds and the crashes fuzzing found (kept in tests/data/fuzz/),
// so each fixed crash stays a regression test in every build, with or without libFuzzer.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz_case.h"
#include "io/volume_loader.h"

namespace ewa::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

std::vector<fs::path> filesIn(const fs::path& folder) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(FuzzReplay, EveryParserHasATargetWithSeeds) {
  for (const char* name : {"nrrd", "metaimage", "dat", "vti", "raw", "tf_json", "archive", "mrc",
                           "vtk", "image", "zarr"}) {
    ASSERT_TRUE(fuzzTargets().count(name)) << name;
    EXPECT_FALSE(filesIn(fs::path(EWA_FUZZ_DIR) / "corpus" / name).empty()) << name;
  }
}

TEST(FuzzReplay, SeedsAndKeptCrashesRunClean) {
  int replayed = 0;
  for (const auto& [name, body] : fuzzTargets()) {
    for (const fs::path& folder :
         {fs::path(EWA_FUZZ_DIR) / "corpus" / name, fs::path(EWA_TEST_DIR) / "data/fuzz" / name}) {
      for (const fs::path& file : filesIn(folder)) {
        const std::vector<uint8_t> input = readAll(file);
        EXPECT_NO_THROW(body(input.data(), input.size())) << name << ": " << file;
        ++replayed;
      }
    }
  }
  EXPECT_GT(replayed, 20);
}

TEST(FuzzReplay, SeedsLoadAsVolumes) {
  // The seeds are valid files: a seed that fails to load would not exercise the data paths.
  ScratchFiles files;
  for (const auto& [name, ext] :
       std::vector<std::pair<std::string, std::string>>{{"nrrd", ".nrrd"},
                                                        {"metaimage", ".mha"},
                                                        {"dat", ".dat"},
                                                        {"vti", ".vti"},
                                                        {"archive", ".zip"},
                                                        {"mrc", ".mrc"},
                                                        {"vtk", ".vtk"},
                                                        {"image", ".png"}}) {
    for (const fs::path& file : filesIn(fs::path(EWA_FUZZ_DIR) / "corpus" / name)) {
      const std::vector<uint8_t> input = readAll(file);
      const std::string path = files.write(input.data(), input.size(), "in" + ext);
      EXPECT_NO_THROW(loadVolume(path)) << file;
    }
  }
}

}  // namespace
}  // namespace ewa::fuzz
