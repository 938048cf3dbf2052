// Side files (transfer functions, bookmarks, settings) that are FIFOs, folders or huge are refused
// at once with one line naming the file, and JSON errors name the file in words.
#include "io/side_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "io/camera_bookmarks.h"
#include "io/transfer_function_io.h"
#include "io/viewer_settings.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::TempDir;

std::string problemOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(SideFile, AFifoIsRefusedWithoutWaitingForAWriter) {
  TempDir dir;
  const std::string fifo = dir.path("tf.json");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  const std::string problem = problemOf([&] { loadTransferFunction(fifo); });
  EXPECT_EQ(problem, fifo + ": is not a regular file, not a transfer-function file");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_NE(problemOf([&] { loadBookmarks(fifo); }).find("not a bookmarks file"),
            std::string::npos);
  EXPECT_NE(problemOf([&] { loadViewerSettings(fifo); }).find("not a settings file"),
            std::string::npos);
  EXPECT_EQ(problemOf([&] { readSideFile("/dev/zero", "bookmarks file"); }),
            "/dev/zero: is not a regular file, not a bookmarks file");
}

TEST(SideFile, AHugeSparseFileIsRefusedBeforeItIsRead) {
  TempDir dir;
  const std::string huge = dir.path("huge.tf.json");
  dir.write("huge.tf.json", "{");
  ASSERT_EQ(truncate(huge.c_str(), off_t(12) << 30), 0);  // 12 GiB of holes, no disk used
  const std::string problem = problemOf([&] { loadTransferFunction(huge); });
  EXPECT_EQ(problem,
            huge + ": is 12288 MiB, too big for a transfer-function file (at most 64 MiB)");
  const std::string folder = dir.path("sub");
  std::filesystem::create_directory(folder);
  EXPECT_EQ(problemOf([&] { readSideFile(folder, "settings file"); }),
            folder + ": is a directory, not a settings file");
}

TEST(SideFile, JsonProblemsAreSaidInWordsNamingTheFile) {
  TempDir dir;
  const std::string path = dir.write("view.bookmarks.json", R"({"bookmarks": [{"name": "a"}]})");
  const std::string problem = problemOf([&] { loadBookmarks(path); });
  EXPECT_EQ(problem.rfind(path + ": ", 0), 0u) << problem;
  EXPECT_EQ(problem.find("[json.exception"), std::string::npos) << problem;
  EXPECT_EQ(problem.find('\n'), std::string::npos) << problem;
  const std::string settings = dir.write("settings.json", R"({"window_size": "big"})");
  const std::string bad = problemOf([&] { loadViewerSettings(settings); });
  EXPECT_EQ(bad.rfind(settings + ": ", 0), 0u) << bad;
  EXPECT_EQ(bad.find("[json.exception"), std::string::npos) << bad;
  EXPECT_EQ(problemText(std::bad_alloc()), "out of memory");
}

}  // namespace
}  // namespace ewa
